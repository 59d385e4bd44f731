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
    graph::ImageHandle add(graph::RenderGraph& g, const FrameInputs& in, uint32_t resolution) const;

private:
    const vk::Context& ctx_;
    shader::Pipeline pipeline_;
    shader::Pipeline maskedPipeline_;
    bool anyMasked_ = false;
};

}  // namespace ppr::passes
