#include "glass_reflect/glass_reflect_pass.hpp"

#include "common/compute_pass.hpp"
#include "glass_reflect/glass_reflect.h"
#include "glass_atlas_view_comp.h"
#include "glass_reflect_comp.h"

namespace ppr::passes {

GlassReflectPass::GlassReflectPass(const vk::Context& ctx) : ctx_(ctx) {
    shader::PipelineLayoutDesc layout;
    layout.pushConstantBytes = sizeof(gpu::GlassReflectPush);
    pipeline_ = shader::createComputePipeline(ctx, PPR_SPIRV(glass_reflect_comp), layout, "ppr.glass.reflect");
    view_ = shader::createComputePipeline(ctx, PPR_SPIRV(glass_atlas_view_comp), {}, "glass.atlas_view");
}

graph::ImageHandle GlassReflectPass::addAtlasView(graph::RenderGraph& g, const FrameInputs& in, graph::ImageHandle reflectionAtlas,
                                                  graph::ImageHandle color) const {
    graph::ImageHandle out;
    ComputePass(g, ctx_, "glass.atlas_view", view_)
        .uniform(in.frameConstants, in.frameConstantsOffset, in.frameConstantsSize)
        .sampled(reflectionAtlas, in.samplers->nearestClamp)
        .storageReadWrite(color, &out)
        .dispatch(in.extent, gpu::kGlassReflectGroupSize);
    return out;
}

void GlassReflectPass::queueClears(graph::RenderGraph& g, TransferBatch& batch, GlassReflectInputs& inputs) {
    const uint32_t size = inputs.atlasSize;
    // Texels outside the regions hold no reflection: cleared (cheap, transfer), not dispatched.
    batch.clearImage(g.createImage("ppr.glass.reflection", {size, size, kFormat, 1}), VkClearColorValue{}, "ppr.glass.reflection.clear",
                     &inputs.clearedTarget.emplace());
}

graph::ImageHandle GlassReflectPass::add(graph::RenderGraph& g, const FrameInputs& in, const GlassReflectInputs& inputs) const {
    graph::ImageHandle target;
    if (inputs.clearedTarget) {
        target = *inputs.clearedTarget;
    } else {
        TransferBatch batch(in);
        GlassReflectInputs own = inputs;
        queueClears(g, batch, own);
        batch.add(g, "ppr.glass.reflection.clear");
        target = *own.clearedTarget;
    }
    if (inputs.blockCount == 0 || inputs.regionCount == 0) return target;
    gpu::GlassReflectPush push{};
    push.regionCount = inputs.regionCount;
    push.flags = inputs.flags;
    graph::ImageHandle out;
    ComputePass(g, ctx_, "ppr.glass.reflect", pipeline_)
        .uniform(in.frameConstants, in.frameConstantsOffset, in.frameConstantsSize)
        .storageRead(inputs.atlas)
        .sampled(inputs.sceneColor, in.samplers->linearClamp)
        .sampled(inputs.sceneColor, in.samplers->nearestClamp)
        .storageRead(inputs.regions)
        .storageRead(inputs.regionList)
        .storageReadWrite(target, &out)
        .storageRead(inputs.blockStarts)
        .push(push)
        .dispatch({inputs.blockCount * gpu::kGlassReflectGroupSize, gpu::kGlassReflectGroupSize}, gpu::kGlassReflectGroupSize);  // a row of blocks
    return out;
}

}  // namespace ppr::passes
