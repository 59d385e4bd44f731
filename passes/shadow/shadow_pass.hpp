#pragma once
// Directional-light shadow map: depth-only render of the scene from the light (reverse-Z ortho).
// Alpha-masked draws (glTF MASK) go through a second pipeline that samples their base colour alpha,
// so a scene without them records exactly the commands it always did.
#include "common/frame_inputs.hpp"
#include "graph/graph.hpp"

namespace ppr::passes {

class ShadowPass {
public:
    static constexpr VkFormat kFormat = VK_FORMAT_D32_SFLOAT;
    static constexpr uint32_t kDefaultResolution = 2048;
    ShadowPass(const vk::Context& ctx, const gpu::GpuScene& scene);
    using Casters = gpu::GpuScene::Subset;
    // A transient map of resolution² texels, drawn this frame.
    graph::ImageHandle add(graph::RenderGraph& g, const FrameInputs& in, uint32_t resolution) const;
    // Draws `casters` into `map` (a kFormat image, e.g. an import that outlives the frame); returns
    // its new version. All and Still clear it first ("shadow"); Moving draws over what it holds
    // ("shadow.moving"). Depth-only with a >= test keeps each texel's nearest depth in any order, so
    // the still casters, then the moving ones, give the map all of them give.
    graph::ImageHandle addInto(graph::RenderGraph& g, const FrameInputs& in, graph::ImageHandle map, Casters casters = Casters::All) const;
    // Copies `from` into `to`, both kFormat of one size ("shadow.restore"); returns `to`'s new version.
    static graph::ImageHandle addRestore(graph::RenderGraph& g, graph::ImageHandle from, graph::ImageHandle to);

private:
    const vk::Context& ctx_;
    shader::Pipeline pipeline_;
    shader::Pipeline maskedPipeline_;
    bool anyMasked_ = false;
};

}  // namespace ppr::passes
