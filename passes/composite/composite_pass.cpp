#include "composite/composite_pass.hpp"

#include "composite_comp.h"
#include "lighting/lighting.h"
#include "lighting/lighting_pass.hpp"

namespace ppr::passes {

CompositePass::CompositePass(const vk::Context& ctx) : ctx_(ctx) {
    shader::PipelineLayoutDesc layout;
    layout.pushBindings = {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER};
    for (int i = 0; i < 6; ++i) layout.pushBindings.push_back(VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER);
    layout.pushBindings.push_back(VK_DESCRIPTOR_TYPE_STORAGE_IMAGE);
    pipeline_ = shader::createComputePipeline(ctx, PPR_SPIRV(composite_comp), layout, "composite");
}

graph::ImageHandle CompositePass::add(graph::RenderGraph& g, const FrameInputs& in, const GBuffer& gb, graph::ImageHandle sceneColor) const {
    struct Data {
        GBuffer gb;
        graph::ImageHandle color, out;
    };
    graph::ImageHandle out = g.createImage("composited", {in.extent.width, in.extent.height, LightingPass::kColorFormat, 1});
    const Data& d = g.addPass<Data>(
        "composite", graph::QueueKind::Compute,
        [&](graph::PassBuilder& b, Data& data) {
            data.color = b.sampled(sceneColor);
            data.gb.depth = b.sampled(gb.depth);
            data.gb.normal = b.sampled(gb.normal);
            data.gb.albedo = b.sampled(gb.albedo);
            data.gb.material = b.sampled(gb.material);
            data.gb.reflector = b.sampled(gb.reflector);
            data.out = b.storageWrite(out);
        },
        [this, in](const Data& data, graph::PassContext& pc) {
            VkCommandBuffer cmd = pc.cmd();
            VkSampler s = in.samplers->nearestClamp;
            pipeline_.bind(cmd);
            shader::PushDescriptors(ctx_)
                .uniformBuffer(in.frameConstants, in.frameConstantsOffset, in.frameConstantsSize)
                .sampled(pc.view(data.color), pc.layout(data.color), s)
                .sampled(pc.view(data.gb.depth), pc.layout(data.gb.depth), s)
                .sampled(pc.view(data.gb.normal), pc.layout(data.gb.normal), s)
                .sampled(pc.view(data.gb.albedo), pc.layout(data.gb.albedo), s)
                .sampled(pc.view(data.gb.material), pc.layout(data.gb.material), s)
                .sampled(pc.view(data.gb.reflector), pc.layout(data.gb.reflector), s)
                .storageImage(pc.view(data.out))
                .push(cmd, pipeline_);
            shader::dispatchCovering(cmd, in.extent, gpu::kLightingGroupSize);
        });
    return d.out;
}

}  // namespace ppr::passes
