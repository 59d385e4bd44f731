#pragma once
// Technique `planar`, the ground truth: for each visible plane group, the scene re-rendered (G-buffer
// + lighting) by the camera mirrored about the plane with an oblique near plane at it
// (engine/scene/mirror.hpp), then resolved onto the group's reflector pixels. Exact for mirrors;
// costs a full scene render per plane, which is why it is the reference and not a technique to ship.
#include "common/frame_inputs.hpp"
#include "common/reflected_path.hpp"
#include "gbuffer/gbuffer_pass.hpp"
#include "lighting/lighting_pass.hpp"

#include <vector>

namespace ppr::passes {

struct PlanarView {
    uint32_t planeGroup = 0;
    FrameInputs in;  // the mirrored view's frame constants
};

// The glass atlas layout of this frame (glass_reflect/glass_regions.hpp), when glass panels are visible.
struct PlanarGlass {
    graph::BufferHandle regions, regionList;
    uint32_t regionCount = 0, atlasSize = 0;
    VkExtent2D used{};  // the atlas texels holding regions, from its corner: the rest is not dispatched
    const std::vector<bool>* planeGroups = nullptr;  // per plane group: does it hold a pane with a region?
};

struct PlanarReflectors {
    VkBuffer data = VK_NULL_HANDLE;  // ReflectorData[count]
    uint32_t count = 0;
};

struct PlanarOutputs {
    graph::ImageHandle reflection;  // common/reflection.h
    graph::ImageHandle path;        // rg32f, planar.h planar.distance: reflected path length and classes
    graph::ImageHandle glass;       // with PlanarGlass: the panels' rgba16f atlas (same layout); else invalid
};

class PlanarPass {
public:
    PlanarPass(const vk::Context& ctx, const GBufferPass& gbuffer, const LightingPass& lighting);
    // Views may be empty (nothing visible). With `glass`, also resolves the glass panels' regions.
    PlanarOutputs add(graph::RenderGraph& g, const FrameInputs& in, const GBuffer& gb, graph::ImageHandle shadowMap,
                      const std::vector<PlanarView>& views, PlanarReflectors reflectors, const PlanarGlass* glass = nullptr) const;
    static constexpr VkFormat kPathFormat = kReflectedPathFormat;

private:
    const vk::Context& ctx_;
    const GBufferPass& gbuffer_;
    const LightingPass& lighting_;
    shader::Pipeline resolve_, glassResolve_;
};

}  // namespace ppr::passes
