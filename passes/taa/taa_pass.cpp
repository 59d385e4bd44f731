#include "taa/taa_pass.hpp"

#include "common/compute_pass.hpp"
#include "taa/taa.h"
#include "taa_comp.h"
#include "taa_reflection_comp.h"
#include "taa_split_comp.h"

namespace ppr::passes {

TaaPass::TaaPass(const vk::Context& ctx) : ctx_(ctx) {
    shader::PipelineLayoutDesc layout;
    layout.pushConstantBytes = sizeof(gpu::TaaPush);
    pipeline_ = shader::createComputePipeline(ctx, PPR_SPIRV(taa_comp), layout, "taa");
    splitPipeline_ = shader::createComputePipeline(ctx, PPR_SPIRV(taa_split_comp), layout, "taa (split)");
    shader::PipelineLayoutDesc reflectionLayout;
    reflectionLayout.pushConstantBytes = sizeof(gpu::TaaReflectionPush);
    reflectionPipeline_ = shader::createComputePipeline(ctx, PPR_SPIRV(taa_reflection_comp), reflectionLayout, "taa.reflection");
}

graph::ImageHandle TaaPass::addReflection(graph::RenderGraph& g, const FrameInputs& in, graph::HistoryStore& history,
                                          const TaaReflectionInputs& inputs) const {
    const graph::HistoryImage h = g.history(history, kReflectionHistoryName, {in.extent.width, in.extent.height, kHistoryFormat, 1});
    gpu::TaaReflectionPush push{};
    push.historyValid = h.previousValid ? 1u : 0u;
    push.mode = inputs.mode;
    push.hasDistance = inputs.distance ? 1u : 0u;
    const VkSampler nearest = in.samplers->nearestClamp;
    graph::ImageHandle shown, written;
    ComputePass(g, ctx_, "taa.reflection", reflectionPipeline_)
        .uniform(in.frameConstants, in.frameConstantsOffset, in.frameConstantsSize)
        .sampled(inputs.reflection, nearest)
        .sampled(inputs.depth, nearest)
        .sampled(inputs.normal, nearest)
        .sampled(inputs.distance.value_or(inputs.depth), nearest)  // unread without a distance (hasDistance 0)
        .sampled(h.previous, in.samplers->linearClamp)
        .storageWrite(g.createImage("taa.reflection.shown", {in.extent.width, in.extent.height, kHistoryFormat, 1}), &shown)
        .storageWrite(h.current, &written)
        .hostStorage(in.motion)  // a moving reflected point's motion slot (the path image's tag)
        .push(push)
        .dispatch(in.extent, gpu::kTaaGroupSize);
    return shown;
}

graph::ImageHandle TaaPass::add(graph::RenderGraph& g, const FrameInputs& in, graph::HistoryStore& history, const TaaInputs& inputs) const {
    const graph::HistoryImage h = g.history(history, kHistoryName, {in.extent.width, in.extent.height, kHistoryFormat, 1});
    gpu::TaaPush push{};
    push.historyValid = h.previousValid ? 1u : 0u;
    push.reflectionMotion = inputs.reflectedPath ? 1u : 0u;
    const VkSampler nearest = in.samplers->nearestClamp;
    graph::ImageHandle out;
    const bool split = inputs.shownReflection.has_value();
    ComputePass pass(g, ctx_, "taa", split ? splitPipeline_ : pipeline_);
    pass.uniform(in.frameConstants, in.frameConstantsOffset, in.frameConstantsSize)
        .sampled(inputs.hdr, nearest)
        .sampled(inputs.depth, nearest)
        .sampled(h.previous, in.samplers->linearClamp)
        .storageWrite(h.current, &out)
        .sampled(inputs.material, nearest)
        .hostStorage(in.motion)
        .sampled(inputs.reflectedPath.value_or(inputs.depth), nearest);  // unread without one (reflectionMotion 0)
    if (split)
        pass.sampled(*inputs.shownReflection, nearest)
            .storageWrite(g.createImage("taa.frame", {in.extent.width, in.extent.height, kHistoryFormat, 1}), &out);
    pass.push(push).dispatch(in.extent, gpu::kTaaGroupSize);
    return out;
}

}  // namespace ppr::passes
