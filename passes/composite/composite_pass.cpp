#include "composite/composite_pass.hpp"

#include "common/compute_pass.hpp"

#include "composite_comp.h"
#include "composite_reflect_comp.h"
#include "lighting/lighting.h"
#include "lighting/lighting_pass.hpp"

namespace ppr::passes {

CompositePass::CompositePass(const vk::Context& ctx) : ctx_(ctx) {
    plain_ = shader::createComputePipeline(ctx, PPR_SPIRV(composite_comp), {}, "composite");
    withReflection_ = shader::createComputePipeline(ctx, PPR_SPIRV(composite_reflect_comp), {}, "composite (reflection)");
}

graph::ImageHandle CompositePass::add(graph::RenderGraph& g, const FrameInputs& in, const GBuffer& gb, graph::ImageHandle sceneColor,
                                      const std::optional<CompositeReflection>& reflection) const {
    const VkSampler s = in.samplers->nearestClamp;
    graph::ImageHandle out;
    ComputePass pass(g, ctx_, "composite", reflection ? withReflection_ : plain_);
    pass.uniform(in.frameConstants, in.frameConstantsOffset, in.frameConstantsSize)
        .sampled(sceneColor, s)
        .sampled(gb.depth, s)
        .sampled(gb.normal, s)
        .sampled(gb.albedo, s)
        .sampled(gb.material, s)
        .sampled(gb.reflector, s)
        .storageWrite(g.createImage("composited", {in.extent.width, in.extent.height, LightingPass::kColorFormat, 1}), &out)
        .hostStorage(in.motion);
    if (reflection) pass.sampled(reflection->image, s).hostStorage(reflection->reflectors);
    pass.dispatch(in.extent, gpu::kLightingGroupSize);
    return out;
}

}  // namespace ppr::passes
