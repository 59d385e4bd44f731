#include "lighting/lighting_pass.hpp"

#include "lighting/lighting.h"
#include "lighting_comp.h"

namespace ppr::passes {

LightingPass::LightingPass(const vk::Context& ctx) : ctx_(ctx) {
    shader::PipelineLayoutDesc layout;
    layout.pushBindings = {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER,         VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
                           VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
                           VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
                           VK_DESCRIPTOR_TYPE_STORAGE_IMAGE};
    pipeline_ = shader::createComputePipeline(ctx, PPR_SPIRV(lighting_comp), layout, "lighting");
}

graph::ImageHandle LightingPass::add(graph::RenderGraph& g, const FrameInputs& in, const GBuffer& gb, graph::ImageHandle shadowMap) const {
    struct Data {
        GBuffer gb;
        graph::ImageHandle shadow, out;
    };
    graph::ImageHandle color = g.createImage("sceneColor", {in.extent.width, in.extent.height, kColorFormat, 1});
    const Data& d = g.addPass<Data>(
        "lighting", graph::QueueKind::Compute,
        [&](graph::PassBuilder& b, Data& data) {
            data.gb.depth = b.sampled(gb.depth);
            data.gb.normal = b.sampled(gb.normal);
            data.gb.albedo = b.sampled(gb.albedo);
            data.gb.material = b.sampled(gb.material);
            data.shadow = b.sampled(shadowMap);
            data.out = b.storageWrite(color);
        },
        [this, in](const Data& data, graph::PassContext& pc) {
            VkCommandBuffer cmd = pc.cmd();
            const shader::Samplers& s = *in.samplers;
            pipeline_.bind(cmd);
            shader::PushDescriptors(ctx_)
                .uniformBuffer(in.frameConstants, in.frameConstantsOffset, in.frameConstantsSize)
                .sampled(pc.view(data.gb.depth), pc.layout(data.gb.depth), s.nearestClamp)
                .sampled(pc.view(data.gb.normal), pc.layout(data.gb.normal), s.nearestClamp)
                .sampled(pc.view(data.gb.albedo), pc.layout(data.gb.albedo), s.nearestClamp)
                .sampled(pc.view(data.gb.material), pc.layout(data.gb.material), s.nearestClamp)
                .sampled(pc.view(data.shadow), pc.layout(data.shadow), s.shadowCompare)
                .storageImage(pc.view(data.out))
                .push(cmd, pipeline_);
            shader::dispatchCovering(cmd, in.extent, gpu::kLightingGroupSize);
        });
    return d.out;
}

}  // namespace ppr::passes
