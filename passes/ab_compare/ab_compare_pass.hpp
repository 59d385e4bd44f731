#pragma once
// The viewer's A/B comparison with the planar ground truth (ab_compare.comp): a split reflection
// image, or an error heat map over the frame.
#include "common/frame_inputs.hpp"
#include "graph/graph.hpp"

namespace ppr::passes {

class AbComparePass {
public:
    explicit AbComparePass(const vk::Context& ctx);
    // "ab.split": a new reflection image, the technique's left of splitX (pixels), the reference's right.
    graph::ImageHandle split(graph::RenderGraph& g, const FrameInputs& in, graph::ImageHandle technique, graph::ImageHandle reference,
                             float splitX) const;
    // "ab.heat": the reflection error drawn over `hdr` (the composited frame); returns its new version.
    graph::ImageHandle heat(graph::RenderGraph& g, const FrameInputs& in, graph::ImageHandle technique, graph::ImageHandle reference,
                            graph::ImageHandle hdr) const;

private:
    graph::ImageHandle add(graph::RenderGraph& g, const FrameInputs& in, const char* name, graph::ImageHandle technique,
                           graph::ImageHandle reference, graph::ImageHandle target, bool fresh, uint32_t mode, float splitX) const;
    const vk::Context& ctx_;
    shader::Pipeline pipeline_;
};

}  // namespace ppr::passes
