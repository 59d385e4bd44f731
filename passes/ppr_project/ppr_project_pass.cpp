#include "ppr_project/ppr_project_pass.hpp"

#include "common/compute_pass.hpp"
#include "ppr_common/tile_culling.h"
#include "ppr_common/tiles.h"
#include "ppr_project/ppr_project.h"
#include "ppr_project_comp.h"

namespace ppr::passes {

static_assert(gpu::kPprCullMinHeight < gpu::kPprAboveEpsilon, "culling must keep every tile the projection can write from");

namespace {
constexpr WorkgroupWidths kWidths{kProjectThreadChoices, gpu::kPprProjectThreads, gpu::kPprProjectThreadsGpu};

// Each invocation projects as many pixels and judges a run of at most 32 reflectors (one bit mask).
static_assert(kWidths.valid(gpu::kPprTileSize * gpu::kPprTileSize, (gpu::kPprMaxReflectors + 31u) / 32u),
              "ppr.project's invocation counts must divide the tile, judge every reflector and hold the defaults");

shader::PipelineLayoutDesc projectLayout() {
    shader::PipelineLayoutDesc layout;
    layout.pushConstantBytes = sizeof(gpu::PprProjectPush);
    return layout;
}
}  // namespace

PprProjectPass::PprProjectPass(const vk::Context& ctx)
    : ctx_(ctx), pipelines_(ctx, PPR_SPIRV(ppr_project_comp), projectLayout(), "ppr.project", kWidths) {}

uint32_t PprProjectPass::autoThreads(const vk::DeviceInfo& device) { return kWidths.defaultFor(device); }

PprProjectOutputs PprProjectPass::add(graph::RenderGraph& g, const FrameInputs& in, const ReflectorBinding& r,
                                      const PprProjectInputs& inputs) const {
    gpu::PprProjectPush push{};
    push.reflectorCount = r.count;
    push.cullTiles = inputs.cullTiles ? 1u : 0u;
    push.tilesX = inputs.tilesX;
    push.cullPlaneCount = r.cullPlanes;
    push.glass = inputs.glass ? 1u : 0u;
    push.facingOnly = inputs.facingOnly ? 1u : 0u;
    push.tileList = inputs.reach ? 1u : 0u;
    push.splat = inputs.splat ? 1u : 0u;
    PprProjectOutputs out;
    const uint32_t tileCount = inputs.tilesX * inputs.tilesY;
    // With a tile list the reach pass has already written the survivor counts of the tiles it left
    // out and counted the tiles with content; without one, the list binding is a stand-in never read.
    const graph::BufferHandle survivors =
        inputs.reach ? inputs.reach->tileSurvivors : g.createBuffer("ppr.tile_survivors", {sizeof(uint32_t) * tileCount});
    ComputePass pass(g, ctx_, "ppr.project", pipelines_.get(inputs.threads));
    pass.uniform(in.frameConstants, in.frameConstantsOffset, in.frameConstantsSize)
        .sampled(inputs.depth, in.samplers->nearestClamp)
        .hostStorage(r.reflectors)
        .hostStorage(r.order)
        .storageReadWrite(inputs.intermediate, &out.intermediate)
        .storageRead(inputs.bounds);
    if (inputs.reach) pass.storageReadWrite(survivors, &out.tileSurvivors);
    else pass.storageWrite(survivors, &out.tileSurvivors);
    pass.storageReadWrite(inputs.reach ? inputs.reach->stats : inputs.stats, &out.stats)
        .hostStorage(r.planeLeaders)
        .storageReadWrite(inputs.glassAtlas, &out.glassAtlas)
        .storageRead(inputs.glassRegions)
        .sampled(inputs.normal, in.samplers->nearestClamp);
    graph::BufferHandle unused;
    if (inputs.reach) pass.storageRead(inputs.reach->tiles);  // binding 12
    else pass.storageWrite(g.createBuffer("ppr.reach.unused", {sizeof(uint32_t)}), &unused);
    pass.storageRead(inputs.visible).push(push);
    if (inputs.reach) pass.dispatchIndirect(inputs.reach->args);
    else pass.dispatch(in.extent, gpu::kPprTileSize);
    return out;
}

}  // namespace ppr::passes
