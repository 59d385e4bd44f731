#pragma once
// TAA resolve (--set taa=1): the jittered HDR frame + the history image ("taa.color", a graph history
// resource) → the new history, which is the frame's anti-aliased HDR output.
#include "common/frame_inputs.hpp"
#include "graph/history.hpp"

namespace ppr::passes {

class TaaPass {
public:
    static constexpr const char* kHistoryName = "taa.color";
    static constexpr VkFormat kHistoryFormat = VK_FORMAT_R16G16B16A16_SFLOAT;

    explicit TaaPass(const vk::Context& ctx);
    graph::ImageHandle add(graph::RenderGraph& g, const FrameInputs& in, graph::HistoryStore& history, graph::ImageHandle hdr,
                           graph::ImageHandle depth) const;

private:
    const vk::Context& ctx_;
    shader::Pipeline pipeline_;
};

}  // namespace ppr::passes
