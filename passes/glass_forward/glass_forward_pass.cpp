#include "glass_forward/glass_forward_pass.hpp"

#include "gbuffer/gbuffer_pass.hpp"
#include "gbuffer_vert.h"
#include "glass_forward/glass_forward.h"
#include "glass_forward_frag.h"
#include "glass_forward_reflect_frag.h"
#include "lighting/lighting_pass.hpp"

#include <algorithm>

namespace ppr::passes {

GlassForwardPass::GlassForwardPass(const vk::Context& ctx, const gpu::GpuScene& scene) : ctx_(ctx) {
    auto build = [&](shader::Spirv frag, const char* name) {
        shader::PipelineLayoutDesc layout;
        layout.stages = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;
        layout.pushConstantBytes = sizeof(gpu::GlassForwardPush);
        layout.extraSets = {scene.textureSetLayout()};
        return shader::GraphicsPipelineBuilder(ctx, name)
            .vertex(PPR_SPIRV(gbuffer_vert))  // the same vertex stage as the G-buffer: identical depth
            .fragment(frag)
            .layout(layout)
            .vertexInput(sizeof(scene::Vertex), sceneVertexAttributes(false))
            .colorFormats({LightingPass::kColorFormat})
            .depth(GBufferPass::kDepthFormat, true, false, VK_COMPARE_OP_GREATER)
            .addAndFilterBlend()
            .build();
    };
    plain_ = build(PPR_SPIRV(glass_forward_frag), "glass");
    withReflection_ = build(PPR_SPIRV(glass_forward_reflect_frag), "glass (reflection)");
}

void GlassForwardPass::sortBackToFront(const gpu::GpuScene& scene, const glm::vec3& eye, std::vector<uint32_t>& order) {
    const scene::Scene& s = scene.cpu();
    order.assign(scene.transparentDraws().begin(), scene.transparentDraws().end());
    auto distance = [&](uint32_t i) {
        const scene::Mesh& m = s.meshes[s.draws[i].mesh];
        const glm::vec3 centre = glm::vec3(s.draws[i].world * glm::vec4((m.boundsMin + m.boundsMax) * 0.5f, 1.0f));
        return glm::length(centre - eye);
    };
    std::sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) { return distance(a) > distance(b); });
}

graph::ImageHandle GlassForwardPass::add(graph::RenderGraph& g, const FrameInputs& in, graph::ImageHandle color, graph::ImageHandle depth,
                                         VkBuffer reflectors, const std::optional<GlassReflection>& reflection,
                                         const std::vector<uint32_t>* order) const {
    struct Data {
        graph::ImageHandle color, depth, atlas;
        graph::BufferHandle regions;
    };
    const shader::Pipeline& pipeline = reflection ? withReflection_ : plain_;
    const Data& d = g.addPass<Data>(
        "glass", graph::QueueKind::Graphics,
        [&](graph::PassBuilder& b, Data& data) {
            data.color = b.colorAttachment(color, graph::LoadOp::Load);
            data.depth = b.depthAttachmentRead(depth);
            if (reflection) {
                data.atlas = b.sampled(reflection->atlas);
                data.regions = b.storageRead(reflection->regions);
            }
        },
        [this, in, reflectors, order, &pipeline, withReflection = reflection.has_value()](const Data& data, graph::PassContext& pc) {
            VkCommandBuffer cmd = pc.cmd();
            pipeline.bind(cmd);
            shader::PushDescriptors push(ctx_);
            push.uniformBuffer(in.frameConstants, in.frameConstantsOffset, in.frameConstantsSize)
                .storageBuffer(in.draws)
                .storageBuffer(in.scene->materialBuffer())
                .storageBuffer(reflectors)
                .storageBuffer(in.drawReflectors)
                .storageBuffer(in.looseGlassReflectors);
            if (withReflection)
                push.storageBuffer(pc.buffer(data.regions)).sampled(pc.view(data.atlas), pc.layout(data.atlas), in.samplers->linearClamp);
            push.push(cmd, pipeline);
            VkDescriptorSet textures = in.scene->textureSet();
            vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline.layout(), 1, 1, &textures, 0, nullptr);
            const uint32_t flags = withReflection ? gpu::kGlassReflections : 0u;
            in.scene->drawInOrder(cmd, *order, [&](uint32_t i) { pipeline.pushConstants(cmd, gpu::GlassForwardPush{i, flags, in.looseGlassCount, 0}); });
        });
    return d.color;
}

}  // namespace ppr::passes
