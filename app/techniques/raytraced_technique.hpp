#pragma once
// The ray-traced reference (docs/raytraced.md): every reflector pixel's mirror ray traced through the
// scene's acceleration structures with VK_KHR_ray_query and its hit lit with the lighting pass's code;
// glass panes the same way in the glass atlas layout. Exact where the planar reference is (flat
// mirrors), and defined where it is not (normal-mapped reflectors, --set normalmap). Reads the
// PprSettings' normalMap and GlassSettings. Also the A/B reference beside any other technique.
//
// Needs ray queries: on a device without them unsupported() says which extension is missing (the CLI
// refuses the technique; the viewer shows the line and draws no reflection).
#include "frame/technique.hpp"
#include "gpu/acceleration_structures.hpp"
#include "raytrace/raytrace_pass.hpp"

#include <memory>

namespace ppr::app {

class RaytracedTechnique final : public Technique {
public:
    explicit RaytracedTechnique(FrameServices& services) : services_(services) {}
    std::optional<graph::ImageHandle> addReflection(TechniqueFrame& frame) override;
    std::optional<graph::ImageHandle> addReference(TechniqueFrame& frame) override;
    std::string unsupported(VkExtent2D) const override { return services_.ctx.rayQueryUnavailableReason(); }

private:
    // The pipelines and the scene's acceleration structures, made the first time the technique
    // records a frame (once per renderer, i.e. per scene load; other techniques never pay for them).
    // False on a device without ray queries.
    bool prepare();
    // Animated scenes: the first call in a frame adds the TLAS rebuild.
    passes::RaytraceInputs inputs(TechniqueFrame& f) const;

    FrameServices& services_;
    std::unique_ptr<passes::RaytracePass> pass_;
    std::unique_ptr<gpu::SceneAccelerationStructures> structures_;
};

}  // namespace ppr::app
