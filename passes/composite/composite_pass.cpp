#include "composite/composite_pass.hpp"

#include "common/compute_pass.hpp"

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
    const VkSampler s = in.samplers->nearestClamp;
    graph::ImageHandle out;
    ComputePass(g, ctx_, "composite", pipeline_)
        .uniform(in.frameConstants, in.frameConstantsOffset, in.frameConstantsSize)
        .sampled(sceneColor, s)
        .sampled(gb.depth, s)
        .sampled(gb.normal, s)
        .sampled(gb.albedo, s)
        .sampled(gb.material, s)
        .sampled(gb.reflector, s)
        .storageWrite(g.createImage("composited", {in.extent.width, in.extent.height, LightingPass::kColorFormat, 1}), &out)
        .dispatch(in.extent, gpu::kLightingGroupSize);
    return out;
}

}  // namespace ppr::passes
