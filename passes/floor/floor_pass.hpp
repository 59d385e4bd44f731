#pragma once
// Technique `floor` (floor.comp): the least any screen-space reflection can cost, one full-screen
// pass that reads depth and the lit scene once and writes one rgba16f value per pixel. `ppr bench`
// reports every technique's ratio to it; it draws no reflection.
#include "common/frame_inputs.hpp"
#include "graph/graph.hpp"

namespace ppr::passes {

class FloorPass {
public:
    explicit FloorPass(const vk::Context& ctx);
    graph::ImageHandle add(graph::RenderGraph& g, const FrameInputs& in, graph::ImageHandle depth, graph::ImageHandle sceneColor) const;

private:
    const vk::Context& ctx_;
    shader::Pipeline pipeline_;
};

}  // namespace ppr::passes
