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

graph::ImageHandle GlassReflectPass::createTarget(graph::RenderGraph& g, uint32_t atlasSize) {
    return g.createImage("ppr.glass.reflection", {atlasSize, atlasSize, kFormat, 1});
}

void GlassReflectPass::queueClears(graph::RenderGraph& g, TransferBatch& batch, GlassReflectInputs& inputs) {
    batch.clearImage(createTarget(g, inputs.atlasSize), VkClearColorValue{}, "ppr.glass.reflection.clear", &inputs.clearedTarget.emplace());
}

graph::ImageHandle GlassReflectPass::add(graph::RenderGraph& g, const FrameInputs& in, const GlassReflectInputs& inputs) const {
    const bool resolves = inputs.blockCount > 0 && inputs.regionCount > 0;
    std::optional<graph::ImageHandle> cleared = inputs.clearedTarget;
    if (!cleared && !resolves) {  // nothing writes the rings: every texel "no reflection"
        TransferBatch batch(in);
        GlassReflectInputs own = inputs;
        queueClears(g, batch, own);
        batch.add(g, "ppr.glass.reflection.clear");
        cleared = own.clearedTarget;
    }
    if (!resolves) return *cleared;
    gpu::GlassReflectPush push{};
    push.regionCount = inputs.regionCount;
    push.flags = inputs.flags;
    graph::ImageHandle out;
    ComputePass pass(g, ctx_, "ppr.glass.reflect", pipeline_);
    pass.uniform(in.frameConstants, in.frameConstantsOffset, in.frameConstantsSize)
        .storageRead(inputs.atlas)
        .sampled(inputs.sceneColor, in.samplers->linearClamp)
        .sampled(inputs.sceneColor, in.samplers->nearestClamp)
        .storageRead(inputs.regions)
        .storageRead(inputs.regionList);
    // Uncleared, it gets every texel it is read at: the regions and their rings.
    if (cleared) pass.storageReadWrite(*cleared, &out);
    else pass.storageWrite(createTarget(g, inputs.atlasSize), &out);
    pass.storageRead(inputs.blockStarts)
        .push(push)
        .dispatch({inputs.blockCount * gpu::kGlassReflectGroupSize, gpu::kGlassReflectGroupSize}, gpu::kGlassReflectGroupSize);  // a row of blocks
    return out;
}

}  // namespace ppr::passes
