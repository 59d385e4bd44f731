#include "shadow/shadow_pass.hpp"

#include "gpu/scene_data.h"
#include "shadow_vert.h"

namespace ppr::passes {

ShadowPass::ShadowPass(const vk::Context& ctx) : ctx_(ctx) {
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
}

graph::ImageHandle ShadowPass::add(graph::RenderGraph& g, const FrameInputs& in, uint32_t resolution) const {
    struct Data {
        graph::ImageHandle map;
    };
    graph::ImageHandle map = g.createImage("shadowMap", {resolution, resolution, kFormat, 1});
    const Data& d = g.addPass<Data>(
        "shadow", graph::QueueKind::Graphics,
        [&](graph::PassBuilder& b, Data& data) { data.map = b.depthAttachment(map, graph::LoadOp::Clear, 0.0f); },
        [this, in](const Data&, graph::PassContext& pc) {
            VkCommandBuffer cmd = pc.cmd();
            pipeline_.bind(cmd);
            shader::PushDescriptors(ctx_)
                .uniformBuffer(in.frameConstants, in.frameConstantsOffset, in.frameConstantsSize)
                .storageBuffer(in.scene->drawBuffer())
                .push(cmd, pipeline_);
            in.scene->drawOpaque(cmd, [&](uint32_t i) { pipeline_.pushConstants(cmd, gpu::DrawPush{i, 0, 0, 0}); });
        });
    return d.map;
}

}  // namespace ppr::passes
