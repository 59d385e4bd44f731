#pragma once
// Directional-light shadow map: depth-only render of the scene from the light (reverse-Z ortho).
#include "common/frame_inputs.hpp"
#include "graph/graph.hpp"

namespace ppr::passes {

class ShadowPass {
public:
    static constexpr VkFormat kFormat = VK_FORMAT_D32_SFLOAT;
    static constexpr uint32_t kDefaultResolution = 2048;
    explicit ShadowPass(const vk::Context& ctx);
    graph::ImageHandle add(graph::RenderGraph& g, const FrameInputs& in, uint32_t resolution) const;

private:
    const vk::Context& ctx_;
    shader::Pipeline pipeline_;
};

}  // namespace ppr::passes
