#include "shadow/shadow_pass.hpp"

#include "gpu/scene_data.h"
#include "shadow_masked_frag.h"
#include "shadow_masked_vert.h"
#include "shadow_vert.h"

namespace ppr::passes {

ShadowPass::ShadowPass(const vk::Context& ctx, const gpu::GpuScene& scene) : ctx_(ctx) {
    shader::PipelineLayoutDesc layout;
    layout.stages = VK_SHADER_STAGE_VERTEX_BIT;
    layout.pushConstantBytes = sizeof(gpu::DrawPush);
    pipeline_ = shader::GraphicsPipelineBuilder(ctx, "shadow")
                    .vertex(PPR_SPIRV(shadow_vert))
                    .layout(layout)
                    .vertexInput(sizeof(scene::Vertex), sceneVertexAttributes(true))
                    .depth(kFormat, true, true, VK_COMPARE_OP_GREATER_OR_EQUAL)
                    .depthBias(-1.5f, -2.0f)  // reverse-Z: bias towards the light is negative
                    .build();
    for (uint32_t i = 0; i < scene.cpu().draws.size(); ++i) anyMasked_ |= scene.masked(i) && !scene.transparent(i);
    if (!anyMasked_) return;
    shader::PipelineLayoutDesc masked;
    masked.stages = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;
    masked.pushConstantBytes = sizeof(gpu::DrawPush);
    masked.extraSets = {scene.textureSetLayout()};
    maskedPipeline_ = shader::GraphicsPipelineBuilder(ctx, "shadow.masked")
                          .vertex(PPR_SPIRV(shadow_masked_vert))
                          .fragment(PPR_SPIRV(shadow_masked_frag))
                          .layout(masked)
                          .vertexInput(sizeof(scene::Vertex), sceneVertexAttributes(false))
                          .depth(kFormat, true, true, VK_COMPARE_OP_GREATER_OR_EQUAL)
                          .depthBias(-1.5f, -2.0f)
                          .build();
}

graph::ImageHandle ShadowPass::add(graph::RenderGraph& g, const FrameInputs& in, uint32_t resolution) const {
    return addInto(g, in, g.createImage("shadowMap", {resolution, resolution, kFormat, 1}));
}

graph::ImageHandle ShadowPass::addInto(graph::RenderGraph& g, const FrameInputs& in, graph::ImageHandle map, Casters casters) const {
    struct Data {
        graph::ImageHandle map;
    };
    const bool over = casters == Casters::Moving;
    const Data& d = g.addPass<Data>(
        over ? "shadow.moving" : "shadow", graph::QueueKind::Graphics,
        [&](graph::PassBuilder& b, Data& data) { data.map = b.depthAttachment(map, over ? graph::LoadOp::Load : graph::LoadOp::Clear, 0.0f); },
        [this, in, casters](const Data&, graph::PassContext& pc) {
            VkCommandBuffer cmd = pc.cmd();
            drawUnmaskedDepth(ctx_, cmd, pipeline_, in, casters);
            if (!anyMasked_) return;
            maskedPipeline_.bind(cmd);
            shader::PushDescriptors(ctx_)
                .uniformBuffer(in.frameConstants, in.frameConstantsOffset, in.frameConstantsSize)
                .storageBuffer(in.draws)
                .storageBuffer(in.scene->materialBuffer())
                .push(cmd, maskedPipeline_);
            VkDescriptorSet textures = in.scene->textureSet();
            vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, maskedPipeline_.layout(), 1, 1, &textures, 0, nullptr);
            in.scene->drawOpaque(cmd, true, casters, [&](uint32_t i) { maskedPipeline_.pushConstants(cmd, gpu::DrawPush{i, 0, 0, 0}); });
        });
    return d.map;
}

graph::ImageHandle ShadowPass::addRestore(graph::RenderGraph& g, graph::ImageHandle from, graph::ImageHandle to) {
    struct Copy {
        graph::ImageHandle from, to;
    };
    return g
        .addPass<Copy>(
            "shadow.restore", graph::QueueKind::Transfer,
            [&](graph::PassBuilder& b, Copy& d) {
                d.from = b.transferSrc(from);
                d.to = b.transferDst(to);
            },
            [](const Copy& d, graph::PassContext& pc) {
                const graph::ImageDesc& size = pc.desc(d.to);
                VkImageCopy region{};
                region.srcSubresource = {VK_IMAGE_ASPECT_DEPTH_BIT, 0, 0, 1};
                region.dstSubresource = region.srcSubresource;
                region.extent = {size.width, size.height, 1};
                vkCmdCopyImage(pc.cmd(), pc.image(d.from), pc.layout(d.from), pc.image(d.to), pc.layout(d.to), 1, &region);
            })
        .to;
}

}  // namespace ppr::passes
