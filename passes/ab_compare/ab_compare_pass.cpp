#include "ab_compare/ab_compare_pass.hpp"

#include "ab_compare/ab_compare.h"
#include "ab_compare_comp.h"
#include "common/compute_pass.hpp"

namespace ppr::passes {

AbComparePass::AbComparePass(const vk::Context& ctx) : ctx_(ctx) {
    shader::PipelineLayoutDesc layout;
    layout.pushConstantBytes = sizeof(gpu::AbComparePush);
    pipeline_ = shader::createComputePipeline(ctx, PPR_SPIRV(ab_compare_comp), layout, "ab");
}

graph::ImageHandle AbComparePass::add(graph::RenderGraph& g, const FrameInputs& in, const char* name, graph::ImageHandle technique,
                                      graph::ImageHandle reference, graph::ImageHandle target, bool fresh, uint32_t mode,
                                      float splitX) const {
    gpu::AbComparePush push{};
    push.mode = mode;
    push.splitX = splitX;
    graph::ImageHandle out;
    ComputePass pass(g, ctx_, name, pipeline_);
    pass.uniform(in.frameConstants, in.frameConstantsOffset, in.frameConstantsSize)
        .sampled(technique, in.samplers->nearestClamp)
        .sampled(reference, in.samplers->nearestClamp);
    if (fresh) pass.storageWrite(target, &out);
    else pass.storageReadWrite(target, &out);
    pass.push(push).dispatch(in.extent, 16);
    return out;
}

graph::ImageHandle AbComparePass::split(graph::RenderGraph& g, const FrameInputs& in, graph::ImageHandle technique,
                                        graph::ImageHandle reference, float splitX) const {
    graph::ImageHandle merged = g.createImage("ab.reflection", {in.extent.width, in.extent.height, VK_FORMAT_R16G16B16A16_SFLOAT, 1});
    return add(g, in, "ab.split", technique, reference, merged, true, gpu::kAbSplit, splitX);
}

graph::ImageHandle AbComparePass::heat(graph::RenderGraph& g, const FrameInputs& in, graph::ImageHandle technique, graph::ImageHandle reference,
                                       graph::ImageHandle hdr) const {
    return add(g, in, "ab.heat", technique, reference, hdr, false, gpu::kAbHeat, 0.0f);
}

}  // namespace ppr::passes
