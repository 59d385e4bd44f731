#include "lighting/lighting_pass.hpp"

#include "common/compute_pass.hpp"

#include "lighting/lighting.h"
#include "lighting_comp.h"
#include "lighting_no_emissive_comp.h"

namespace ppr::passes {

LightingPass::LightingPass(const vk::Context& ctx) : ctx_(ctx) {
    pipeline_ = shader::createComputePipeline(ctx, PPR_SPIRV(lighting_comp), {}, "lighting");
    noEmissivePipeline_ = shader::createComputePipeline(ctx, PPR_SPIRV(lighting_no_emissive_comp), {}, "lighting.no_emissive");
}

graph::ImageHandle LightingPass::add(graph::RenderGraph& g, const FrameInputs& in, const GBuffer& gb, graph::ImageHandle shadowMap,
                                     const std::string& name, graph::ImageHandle target) const {
    const shader::Samplers& s = *in.samplers;
    if (!target.valid()) target = g.createImage("sceneColor", {in.extent.width, in.extent.height, kColorFormat, 1});
    graph::ImageHandle out;
    const bool emissive = gb.emissive.valid();
    ComputePass pass(g, ctx_, name, emissive ? pipeline_ : noEmissivePipeline_);
    pass.uniform(in.frameConstants, in.frameConstantsOffset, in.frameConstantsSize)
        .sampled(gb.depth, s.nearestClamp)
        .sampled(gb.normal, s.nearestClamp)
        .sampled(gb.albedo, s.nearestClamp)
        .sampled(gb.material, s.nearestClamp)
        .sampled(shadowMap, s.shadowCompare)
        .storageWrite(target, &out);
    if (emissive) pass.sampled(gb.emissive, s.nearestClamp);
    pass.dispatch(in.extent, gpu::kLightingGroupSize);
    return out;
}

}  // namespace ppr::passes
