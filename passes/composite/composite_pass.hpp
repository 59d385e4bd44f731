#pragma once
// Composite: lit scene (+ reflections in later issues) and G-buffer debug views → HDR colour.
#include "common/frame_inputs.hpp"
#include "gbuffer/gbuffer_pass.hpp"

namespace ppr::passes {

class CompositePass {
public:
    explicit CompositePass(const vk::Context& ctx);
    graph::ImageHandle add(graph::RenderGraph& g, const FrameInputs& in, const GBuffer& gb, graph::ImageHandle sceneColor) const;

private:
    const vk::Context& ctx_;
    shader::Pipeline pipeline_;
};

}  // namespace ppr::passes
