#pragma once
// The glass forward pass (glass_forward_body.glsl): transparent surfaces drawn over the composited
// opaque scene, back to front, depth-tested against the opaque depth (not written), adding their
// reflection and filtering what shows through (dual-source blending).
#include "common/frame_inputs.hpp"
#include "graph/graph.hpp"

#include <optional>
#include <vector>

namespace ppr::passes {

// The glass reflection of this frame: the atlas (rgba16f, common/reflection.h) and where each panel's
// region lies in it (GlassRegionData per reflector index, glass_reflect/glass_regions.hpp).
struct GlassReflection {
    graph::ImageHandle atlas;
    graph::BufferHandle regions;
};

class GlassForwardPass {
public:
    GlassForwardPass(const vk::Context& ctx, const gpu::GpuScene& scene);
    // Draws `order` (transparent draw indices, back to front; must outlive the frame's recording)
    // into `color`; returns its new version. Without `reflection`, glass only transmits.
    graph::ImageHandle add(graph::RenderGraph& g, const FrameInputs& in, graph::ImageHandle color, graph::ImageHandle depth,
                           VkBuffer reflectors, const std::optional<GlassReflection>& reflection, const std::vector<uint32_t>* order) const;
    // Back-to-front order of the scene's transparent draws seen from `eye`, into `order` (reused).
    static void sortBackToFront(const gpu::GpuScene& scene, const glm::vec3& eye, std::vector<uint32_t>& order);

private:
    const vk::Context& ctx_;
    shader::Pipeline plain_, withReflection_;
};

}  // namespace ppr::passes
