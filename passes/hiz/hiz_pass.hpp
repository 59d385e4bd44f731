#pragma once
// Builds the depth hierarchy (hiz.h) from the G-buffer depth: one pass per level from 1 up,
// "hiz.build.<L>", so the build is timed on its own (level 0 is the depth buffer itself).
#include "common/frame_inputs.hpp"
#include "graph/graph.hpp"

namespace ppr::passes {

struct HizAtlas {
    graph::ImageHandle image;  // r32f, hizAtlasSize(hizPaddedSize(screen))
    uint32_t levels = 0;
};

class HizPass {
public:
    static constexpr VkFormat kFormat = VK_FORMAT_R32_SFLOAT;
    explicit HizPass(const vk::Context& ctx);
    HizAtlas add(graph::RenderGraph& g, const FrameInputs& in, graph::ImageHandle depth) const;

private:
    const vk::Context& ctx_;
    shader::Pipeline pipeline_;
};

}  // namespace ppr::passes
