#include "ppr_reflect/ppr_reflect_pass.hpp"

#include "common/clear_pass.hpp"
#include "common/reflected_path.hpp"
#include "common/compute_pass.hpp"
#include "common/dispatch_args.hpp"
#include "common/frame.h"
#include "env_probe/env_probe.h"
#include "ppr_common/tiles.h"
#include "ppr_reflect/ppr_reflect.h"
#include "ppr_reflect_comp.h"

#include <cstddef>

namespace ppr::passes {

PprReflectPass::PprReflectPass(const vk::Context& ctx) : ctx_(ctx) {
    shader::PipelineLayoutDesc layout;
    layout.pushConstantBytes = sizeof(gpu::PprReflectPush);
    pipeline_ = shader::createComputePipeline(ctx, PPR_SPIRV(ppr_reflect_comp), layout, "ppr.reflect");
}

namespace {
// Whether the pass dispatches over the planar tiles: the debug views that draw outside reflector
// pixels need the whole screen.
bool dispatchesIndirect(const PprReflectInputs& inputs) {
    return (inputs.flags & gpu::kPprIndirect) != 0 && inputs.debugView != gpu::kDebugIntermediate && inputs.debugView != gpu::kDebugTiles;
}

graph::BufferHandle createHoleState(graph::RenderGraph& g, uint32_t tileCount) {
    return g.createBuffer("ppr.holes.state", {sizeof(gpu::TileDispatchArgs) + sizeof(uint32_t) * tileCount});
}
}  // namespace

void PprReflectPass::queueClears(graph::RenderGraph& g, TransferBatch& batch, VkExtent2D extent, PprReflectInputs& inputs) {
    if (inputs.listMappedHoles && dispatchesIndirect(inputs) && !inputs.clearedHoles)
        // The list empty and no planar-list slot listed yet.
        batch.emptyDispatchList(createHoleState(g, gpu::pprTilesCovering(extent.width) * gpu::pprTilesCovering(extent.height)), true,
                                &inputs.clearedHoles.emplace());
}

graph::ImageHandle PprReflectPass::add(graph::RenderGraph& g, const FrameInputs& in, const PprReflectInputs& inputs,
                                       graph::ImageHandle* distanceOut, std::optional<TileLists>* mappedHolesOut) const {
    gpu::PprReflectPush push{};
    push.flags = inputs.flags;
    push.debugView = inputs.debugView;
    push.tilesX = inputs.tiles->tilesX;
    push.maxReflectorId = inputs.maxReflectorId;
    if ((push.flags & gpu::kPprEnvironment) && inputs.environment.probe) push.flags |= gpu::kPprEnvironmentProbe;
    const bool indirect = dispatchesIndirect(inputs);
    if (!indirect) push.flags &= ~gpu::kPprIndirect;

    graph::ImageHandle target = g.createImage("reflection", {in.extent.width, in.extent.height, kReflectionFormat, 1});
    // Tiles left out of the indirect dispatch hold no reflector pixel: "no reflection" (all zero),
    // exactly what the whole-screen dispatch writes there.
    if (indirect) target = addClearPass(g, in, "ppr.reflection.clear", target, VkClearColorValue{});
    graph::ImageHandle out;
    ComputePass pass(g, ctx_, "ppr.reflect", pipeline_);
    pass.uniform(in.frameConstants, in.frameConstantsOffset, in.frameConstantsSize)
        .storageRead(inputs.intermediate)
        .sampled(inputs.sceneColor, in.samplers->linearClamp)
        .sampled(inputs.sceneColor, in.samplers->nearestClamp)
        .sampled(inputs.reflectorIds, in.samplers->nearestClamp);
    // Indirect: only some tiles are written, the cleared rest is kept.
    if (indirect) pass.storageReadWrite(target, &out);
    else pass.storageWrite(target, &out);
    pass.storageRead(inputs.tiles->lists)
        .storageRead(inputs.tileSurvivors)
        .sampled(inputs.depth, in.samplers->nearestClamp)
        .sampled(inputs.normal, in.samplers->nearestClamp)
        .hostStorage(inputs.reflectors)
        .uniform(inputs.environment.probeData, 0, sizeof(gpu::EnvProbeData))
        .sampled(inputs.environment.probeCube, in.samplers->linearClamp);
    // Without kPprWriteDistance the shader never touches binding 13: a 1x1 stand-in keeps it bound.
    const bool writeDistance = inputs.distance.has_value();
    if (writeDistance) push.flags |= gpu::kPprWriteDistance;
    graph::ImageHandle distanceWritten;
    // Cleared first and kept where the shader does not write (tiles outside the indirect dispatch).
    if (writeDistance) pass.storageReadWrite(addClearPass(g, in, "ppr.distance.clear", *inputs.distance, VkClearColorValue{}), &distanceWritten);
    else pass.storageWrite(g.createImage("ppr.distance.unused", {1, 1, kReflectedPathFormat, 1}), &distanceWritten);
    pass.sampled(inputs.material, in.samplers->nearestClamp);  // binding 14
    // Bindings 15, 16: the mapped holes' tile list (its dispatch arguments and listed slots; the tiles),
    // or 16-byte stand-ins the shader never touches.
    const bool listHoles = indirect && inputs.listMappedHoles && mappedHolesOut;
    TileLists holes;
    if (listHoles) {
        push.flags |= gpu::kPprListMappedHoles;
        holes = *inputs.tiles;
        // The list empty and no planar-list slot listed yet (queueClears).
        const graph::BufferHandle state =
            inputs.clearedHoles ? *inputs.clearedHoles : addEmptyDispatchList(g, "ppr.holes.clear", createHoleState(g, holes.tileCount()), true);
        pass.storageReadWrite(state, &holes.args).storageWrite(g.createBuffer("ppr.holes.tiles", {sizeof(uint32_t) * holes.tileCount()}), &holes.lists);
    } else {
        pass.storageWrite(g.createBuffer("ppr.holes.state.unused", {16}), nullptr).storageWrite(g.createBuffer("ppr.holes.tiles.unused", {16}), nullptr);
    }
    pass.push(push);
    if (indirect) pass.dispatchIndirect(inputs.tiles->args, sizeof(gpu::TileDispatchArgs) * gpu::kTileClassPlanar);
    else pass.dispatch(in.extent, gpu::kPprTileSize);
    if (distanceOut) *distanceOut = distanceWritten;  // set by dispatch
    if (listHoles) {
        *mappedHolesOut = holes;  // args and lists set by dispatch
        // The list's length into the host-visible stats (report.json's tiles_mapped_holes).
        if (inputs.stats.valid())
            addCountCopy(g, "ppr.holes.count", holes.args, offsetof(gpu::TileDispatchArgs, x), inputs.stats,
                         offsetof(gpu::PprFrameStats, tilesWithMappedHoles), sizeof(uint32_t));
    }
    return out;
}

}  // namespace ppr::passes
