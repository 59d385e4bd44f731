#include "ssr_common/ssr_trace_pass.hpp"

#include "common/clear_pass.hpp"
#include "common/reflected_path.hpp"
#include "common/compute_pass.hpp"
#include "env_probe/env_probe.h"
#include "ppr_common/tiles.h"

namespace ppr::passes {

SsrTracePass::SsrTracePass(const vk::Context& ctx, shader::Spirv spirv, std::string name, bool usesHiz)
    : ctx_(ctx), name_(std::move(name)), usesHiz_(usesHiz) {
    shader::PipelineLayoutDesc layout;
    layout.pushConstantBytes = sizeof(gpu::SsrPush);
    pipeline_ = shader::createComputePipeline(ctx, spirv, layout, name_);
}

graph::ImageHandle SsrTracePass::trace(graph::RenderGraph& g, const FrameInputs& in, const SsrInputs& inputs, graph::ImageHandle target,
                                       const std::string& passName, uint32_t pixelClasses, std::optional<uint32_t> listClass,
                                       bool fresh, graph::ImageHandle* distance, uint32_t flags) const {
    gpu::SsrPush push{};
    push.flags = flags;
    push.maxDistance = inputs.params.maxDistance;
    push.thickness = inputs.params.thickness;
    push.thicknessScale = inputs.params.thicknessScale;
    push.maxSteps = inputs.params.maxSteps;
    push.pixelClasses = pixelClasses;
    push.tileCount = inputs.tiles->tileCount();
    push.hizLevels = inputs.hizLevels;
    if (listClass) {
        push.flags |= gpu::kSsrIndirect;
        push.listClass = *listClass;
    } else if (fresh) {
        push.flags |= gpu::kSsrWriteAll;
    }
    if (inputs.mappedNormals) push.flags |= gpu::kSsrMappedNormals;
    if (inputs.environment.fallback) push.flags |= gpu::kSsrEnvironment;
    if (inputs.environment.probe) push.flags |= gpu::kSsrEnvironmentProbe;
    if (distance) push.flags |= gpu::kSsrWriteDistance;
    if (inputs.params.hizSkip) push.flags |= gpu::kSsrHizSkip;
    const GBuffer& gb = *inputs.gbuffer;
    const VkSampler point = in.samplers->nearestClamp;
    graph::ImageHandle out;
    ComputePass pass(g, ctx_, passName, pipeline_);
    pass.uniform(in.frameConstants, in.frameConstantsOffset, in.frameConstantsSize)
        .sampled(gb.depth, point)
        .sampled(gb.normal, point)
        .sampled(gb.material, point)
        .sampled(gb.reflector, point)
        .sampled(inputs.sceneColor, in.samplers->linearClamp)
        .hostStorage(inputs.reflectors)
        .storageRead(inputs.tiles->lists);
    // A whole-screen pass into a fresh image writes every pixel; otherwise untouched pixels are kept.
    if (fresh && !listClass) pass.storageWrite(target, &out);
    else pass.storageReadWrite(target, &out);
    // Path lengths beside it, written the same way; without them a 1×1 stand-in the shader never writes.
    if (!distance) pass.storageWrite(g.createImage(passName + ".distance.unused", {1, 1, kReflectedPathFormat, 1}), nullptr);
    else if (fresh && !listClass) pass.storageWrite(*distance, distance);
    else pass.storageReadWrite(*distance, distance);
    pass.uniform(inputs.environment.probeData, 0, sizeof(gpu::EnvProbeData)).sampled(inputs.environment.probeCube, in.samplers->linearClamp);
    if (usesHiz_) pass.storageRead(*inputs.hiz);
    pass.push(push);
    if (listClass) pass.dispatchIndirect(inputs.tiles->args, sizeof(gpu::TileDispatchArgs) * *listClass);
    else pass.dispatch(in.extent, gpu::kPprTileSize);
    return out;
}

graph::ImageHandle SsrTracePass::addTechnique(graph::RenderGraph& g, const FrameInputs& in, const SsrInputs& inputs,
                                              graph::ImageHandle* distanceOut) const {
    graph::ImageHandle image = g.createImage("reflection", {in.extent.width, in.extent.height, kReflectionFormat, 1});
    if (distanceOut) *distanceOut = g.createImage(name_ + ".distance", {in.extent.width, in.extent.height, kReflectedPathFormat, 1});
    const uint32_t all = (1u << gpu::kTileClassPlanar) | (1u << gpu::kTileClassOther);
    if (!inputs.indirect) return trace(g, in, inputs, image, name_, all, std::nullopt, true, distanceOut);
    // Tiles in neither list hold no reflective pixel: "no reflection" (all zero), as the whole-screen
    // pass writes there. A tile in both lists has each pixel shaded by exactly one of the passes.
    image = addClearPass(g, in, name_ + ".clear", image, VkClearColorValue{});
    if (distanceOut) *distanceOut = addClearPass(g, in, name_ + ".distance.clear", *distanceOut, VkClearColorValue{});
    image = trace(g, in, inputs, image, name_ + ".planar", 1u << gpu::kTileClassPlanar, gpu::kTileClassPlanar, false, distanceOut);
    return trace(g, in, inputs, image, name_ + ".other", 1u << gpu::kTileClassOther, gpu::kTileClassOther, false, distanceOut);
}

graph::ImageHandle SsrTracePass::addFallback(graph::RenderGraph& g, const FrameInputs& in, const SsrInputs& inputs,
                                             graph::ImageHandle reflection, const std::string& passName, bool holes,
                                             graph::ImageHandle* distance, const TileLists* holeTiles) const {
    const std::optional<uint32_t> list = inputs.indirect ? std::optional<uint32_t>(gpu::kTileClassOther) : std::nullopt;
    reflection = trace(g, in, inputs, reflection, passName, 1u << gpu::kTileClassOther, list, false, distance);
    if (!holes) return reflection;
    if (holeTiles) {
        SsrInputs listed = inputs;
        listed.tiles = holeTiles;
        return trace(g, in, listed, reflection, passName + ".holes", 1u << gpu::kTileClassPlanar, 0u, false, distance,
                     gpu::kSsrHolesOnly);
    }
    const std::optional<uint32_t> planar = inputs.indirect ? std::optional<uint32_t>(gpu::kTileClassPlanar) : std::nullopt;
    return trace(g, in, inputs, reflection, passName + ".holes", 1u << gpu::kTileClassPlanar, planar, false, distance, gpu::kSsrHolesOnly);
}

}  // namespace ppr::passes
