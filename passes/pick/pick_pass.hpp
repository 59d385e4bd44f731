#pragma once
// The reflector editor's pick (pick.comp): the G-buffer under one pixel into a host-visible buffer.
#include "common/frame_inputs.hpp"
#include "gbuffer/gbuffer_pass.hpp"
#include "graph/graph.hpp"

namespace ppr::passes {

class PickPass {
public:
    explicit PickPass(const vk::Context& ctx);
    // Pass "pick": writes a PickResult (pick.h) for `pixel` into `result` (an imported host buffer).
    void add(graph::RenderGraph& g, const FrameInputs& in, const GBuffer& gb, glm::ivec2 pixel, graph::BufferHandle result) const;

private:
    const vk::Context& ctx_;
    shader::Pipeline pipeline_;
};

}  // namespace ppr::passes
