#include "tonemap/tonemap_pass.hpp"

#include "fullscreen_vert.h"
#include "tonemap/tonemap.h"
#include "tonemap_frag.h"

#include <stdexcept>

namespace ppr::passes {

void TonemapPass::prepare(VkFormat format) {
    if (pipelines_.count(format)) return;
    shader::PipelineLayoutDesc layout;
    layout.stages = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;
    layout.pushConstantBytes = sizeof(gpu::TonemapPush);
    pipelines_.emplace(format, shader::GraphicsPipelineBuilder(ctx_, "tonemap")
                                   .vertex(PPR_SPIRV(fullscreen_vert))
                                   .fragment(PPR_SPIRV(tonemap_frag))
                                   .layout(layout)
                                   .colorFormats({format})
                                   .build());
}

graph::ImageHandle TonemapPass::add(graph::RenderGraph& g, const FrameInputs& in, graph::ImageHandle hdr, graph::ImageHandle target) const {
    struct Data {
        graph::ImageHandle hdr, target;
    };
    const Data& d = g.addPass<Data>(
        "tonemap", graph::QueueKind::Graphics,
        [&](graph::PassBuilder& b, Data& data) {
            data.hdr = b.sampled(hdr);
            data.target = b.colorAttachment(target, graph::LoadOp::DontCare);
        },
        [this, in](const Data& data, graph::PassContext& pc) {
            auto it = pipelines_.find(pc.desc(data.target).format);
            if (it == pipelines_.end()) throw std::logic_error("tonemap: prepare() was not called for the target format");
            const shader::Pipeline& p = it->second;
            // A target larger than the frame (the viewer's render scale) is upscaled bilinearly.
            const graph::ImageDesc& source = pc.desc(data.hdr);
            const graph::ImageDesc& shown = pc.desc(data.target);
            gpu::TonemapPush push{};
            push.upscale = source.width != shown.width || source.height != shown.height ? 1u : 0u;
            push.invTargetSize = {1.0f / static_cast<float>(shown.width), 1.0f / static_cast<float>(shown.height)};
            VkCommandBuffer cmd = pc.cmd();
            p.bind(cmd);
            shader::PushDescriptors(ctx_)
                .uniformBuffer(in.frameConstants, in.frameConstantsOffset, in.frameConstantsSize)
                .sampled(pc.view(data.hdr), pc.layout(data.hdr), push.upscale ? in.samplers->linearClamp : in.samplers->nearestClamp)
                .push(cmd, p);
            p.pushConstants(cmd, push);
            vkCmdDraw(cmd, 3, 1, 0, 0);
        });
    return d.target;
}

}  // namespace ppr::passes
