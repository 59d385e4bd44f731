#include "taa/taa_pass.hpp"

#include "common/compute_pass.hpp"
#include "common/transfer_batch.hpp"
#include "taa/taa.h"
#include "taa/taa_threads.hpp"
#include "taa_average_comp.h"
#include "taa_comp.h"
#include "taa_reflection_average_comp.h"
#include "taa_reflection_comp.h"
#include "taa_split_average_comp.h"
#include "taa_split_comp.h"

namespace ppr::passes {

namespace {
constexpr WorkgroupWidths kWidths{kTaaThreadChoices, gpu::kTaaThreads, gpu::kTaaThreadsGpu};
static_assert(kWidths.valid(gpu::kTaaTileSize * gpu::kTaaTileSize, gpu::kTaaTileSize),
              "taa_threads: every choice must give each invocation whole columns' rows of the tile, and hold the defaults");

// An image the pass writes: over all of it, or, `cleared` first, where it stores (the rest kept).
void bindOutput(ComputePass& pass, graph::ImageHandle image, bool cleared, graph::ImageHandle* written) {
    if (cleared) pass.storageReadWrite(image, written);
    else pass.storageWrite(image, written);
}

// A still run's range or moments (taa_color.glsl), or with taa_still_spread=0 stand-ins the shader never
// touches (its stillSpread is 0): no history image, and no store per pixel.
void bindSpread(graph::RenderGraph& g, ComputePass& pass, const std::optional<graph::HistoryImage>& spread, bool cleared,
                const char* standInName, graph::ImageHandle unread, VkSampler nearest) {
    if (spread) bindOutput(pass.sampled(spread->previous, nearest), spread->current, cleared, nullptr);
    else pass.sampled(unread, nearest).storageWrite(g.createImage(standInName, {1, 1, TaaPass::kSamplesFormat, 1}), nullptr);
}

shader::PipelineLayoutDesc layoutFor(uint32_t pushBytes) {
    shader::PipelineLayoutDesc layout;
    layout.pushConstantBytes = pushBytes;
    return layout;
}
}  // namespace

TaaPass::TaaPass(const vk::Context& ctx)
    : ctx_(ctx),
      pipelines_{{WidthPipelines(ctx, PPR_SPIRV(taa_comp), layoutFor(sizeof(gpu::TaaPush)), "taa", kWidths),
                  WidthPipelines(ctx, PPR_SPIRV(taa_average_comp), layoutFor(sizeof(gpu::TaaPush)), "taa (average)", kWidths)},
                 {WidthPipelines(ctx, PPR_SPIRV(taa_split_comp), layoutFor(sizeof(gpu::TaaPush)), "taa (split)", kWidths),
                  WidthPipelines(ctx, PPR_SPIRV(taa_split_average_comp), layoutFor(sizeof(gpu::TaaPush)), "taa (split, average)", kWidths)}},
      reflectionPipelines_{
          WidthPipelines(ctx, PPR_SPIRV(taa_reflection_comp), layoutFor(sizeof(gpu::TaaReflectionPush)), "taa.reflection", kWidths),
          WidthPipelines(ctx, PPR_SPIRV(taa_reflection_average_comp), layoutFor(sizeof(gpu::TaaReflectionPush)), "taa.reflection (average)",
                         kWidths)} {}

uint32_t TaaPass::autoThreads(const vk::DeviceInfo& device) { return kWidths.defaultFor(device); }

TaaReflectionOutput TaaPass::addReflection(graph::RenderGraph& g, const FrameInputs& in, graph::HistoryStore& history,
                                          const TaaReflectionInputs& inputs) const {
    graph::HistoryImage h = g.history(history, kReflectionHistoryName, {in.extent.width, in.extent.height, kHistoryFormat, 1});
    std::optional<graph::HistoryImage> samples;
    std::optional<graph::HistoryImage> spread;
    if (inputs.average) {
        samples = g.history(history, kReflectionSamplesName, {in.extent.width, in.extent.height, kSamplesFormat, 1});
        if (inputs.stillSpread) spread = g.history(history, kReflectionSpreadName, {in.extent.width, in.extent.height, kSamplesFormat, 1});
    }
    gpu::TaaReflectionPush push{};
    push.historyValid = h.previousValid && (!samples || samples->previousValid) && (!spread || spread->previousValid) ? 1u : 0u;
    push.mode = inputs.mode;
    push.hasDistance = inputs.distance ? 1u : 0u;
    push.stillSpread = inputs.stillSpread ? gpu::kTaaSpreadSigma : 0.0f;
    push.motionCap = inputs.motionCap ? gpu::kTaaMotionCap : 0.0f;
    push.rimKeep = inputs.rimKeep ? 1u : 0u;
    push.stillRange = inputs.stillRange ? 1u : 0u;
    push.stillKeep = inputs.stillKeep ? 1u : 0u;
    push.movingEdge = inputs.movingEdge ? 1u : 0u;
    // Where clears are transfers (a memset on a CPU device), the images the pass writes are cleared first
    // and a pixel with no reflection and nothing kept, most of the screen, stores nothing to them; a
    // GPU's compute clear would write what those stores write, so there the pass writes every pixel. The
    // cleared versions replace the images' current versions in place.
    graph::ImageHandle shownOut = g.createImage("taa.reflection.shown", {in.extent.width, in.extent.height, kHistoryFormat, 1});
    if (!in.computeClear) {
        TransferBatch clears;  // one transfer pass for all of them
        for (graph::ImageHandle* image : {&shownOut, &h.current, samples ? &samples->current : nullptr, spread ? &spread->current : nullptr})
            if (image) clears.clearImage(*image, VkClearColorValue{}, "taa.reflection.clear", image);
        clears.add(g, "taa.reflection.clear");
        push.clearedNone = 1u;
    }
    const VkSampler nearest = in.samplers->nearestClamp;
    graph::ImageHandle shown, written;
    ComputePass pass(g, ctx_, "taa.reflection", reflectionPipelines_[inputs.average ? 1 : 0].get(inputs.threads));
    pass.uniform(in.frameConstants, in.frameConstantsOffset, in.frameConstantsSize)
        .sampled(inputs.reflection, nearest)
        .sampled(inputs.depth, nearest)
        .sampled(inputs.normal, nearest)
        .sampled(inputs.distance.value_or(inputs.depth), nearest)  // unread without a distance (hasDistance 0)
        .sampled(h.previous, in.samplers->linearClamp);
    const bool cleared = push.clearedNone != 0u;
    bindOutput(pass, shownOut, cleared, &shown);
    bindOutput(pass, h.current, cleared, &written);
    pass.hostStorage(in.motion);  // a moving reflected point's motion slot (the path image's tag)
    if (samples) {
        bindOutput(pass.sampled(samples->previous, in.samplers->linearClamp), samples->current, cleared, nullptr);
        bindSpread(g, pass, spread, cleared, "taa.reflection.spread.unused", inputs.depth, nearest);
    }
    pass.push(push).dispatch(in.extent, gpu::kTaaTileSize);
    return {shown, written};
}

graph::ImageHandle TaaPass::add(graph::RenderGraph& g, const FrameInputs& in, graph::HistoryStore& history, const TaaInputs& inputs) const {
    const graph::HistoryImage h = g.history(history, kHistoryName, {in.extent.width, in.extent.height, kHistoryFormat, 1});
    std::optional<graph::HistoryImage> samples;
    std::optional<graph::HistoryImage> spread;
    if (inputs.average) {
        samples = g.history(history, kSamplesName, {in.extent.width, in.extent.height, kSamplesFormat, 1});
        if (inputs.stillSpread) spread = g.history(history, kSpreadName, {in.extent.width, in.extent.height, kSamplesFormat, 1});
    }
    gpu::TaaPush push{};
    push.historyValid = h.previousValid && (!samples || samples->previousValid) && (!spread || spread->previousValid) ? 1u : 0u;
    push.reflectionMotion = inputs.reflectedPath ? 1u : 0u;
    push.motionCap = inputs.motionCap ? gpu::kTaaMotionCap : 0.0f;
    push.stillSpread = inputs.stillSpread ? gpu::kTaaSpreadSigma : 0.0f;
    push.stillRange = inputs.stillRange ? 1u : 0u;
    push.movingFilter = inputs.movingFilter ? 1u : 0u;
    const VkSampler nearest = in.samplers->nearestClamp;
    graph::ImageHandle out;
    const bool split = inputs.shownReflection.has_value();
    ComputePass pass(g, ctx_, "taa", pipelines_[split ? 1 : 0][inputs.average ? 1 : 0].get(inputs.threads));
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
    if (samples) {
        pass.sampled(samples->previous, in.samplers->linearClamp).storageWrite(samples->current, nullptr);
        if (split) pass.sampled(inputs.reflectionHistory.value_or(inputs.depth), nearest);  // unread without one (pc.keptReflection 0)
        bindSpread(g, pass, spread, false, "taa.color.spread.unused", inputs.depth, nearest);
    }
    push.keptReflection = split && samples && inputs.reflectionHistory ? 1u : 0u;
    pass.push(push).dispatch(in.extent, gpu::kTaaTileSize);
    return out;
}

}  // namespace ppr::passes
