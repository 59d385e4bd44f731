#pragma once
// HDR → display: exposure, ACES fit, sRGB encoding, into an 8-bit UNORM target (capture image or
// swapchain image). One pipeline per target format, created on first use of that format. A target
// larger than the HDR image (the viewer's render scale) is filled by bilinear upscaling.
#include "common/frame_inputs.hpp"
#include "graph/graph.hpp"

#include <map>

namespace ppr::passes {

class TonemapPass {
public:
    explicit TonemapPass(const vk::Context& ctx) : ctx_(ctx) {}
    void prepare(VkFormat targetFormat);  // creates the pipeline for this format (not on the hot path)
    graph::ImageHandle add(graph::RenderGraph& g, const FrameInputs& in, graph::ImageHandle hdr, graph::ImageHandle target) const;

private:
    const vk::Context& ctx_;
    std::map<VkFormat, shader::Pipeline> pipelines_;
};

}  // namespace ppr::passes
