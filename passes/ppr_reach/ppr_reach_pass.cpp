#include "ppr_reach/ppr_reach_pass.hpp"

#include "common/compute_pass.hpp"
#include "common/tile_group_grid.hpp"
#include "hiz/hiz.h"
#include "ppr_common/tiles.h"
#include "ppr_reach/ppr_reach.h"
#include "ppr_reach_comp.h"

#include <stdexcept>

namespace ppr::passes {

namespace {
constexpr WorkgroupWidths kWidths{kReachThreadChoices, gpu::kPprReachThreads, gpu::kPprReachThreadsGpu};

// One invocation's tile is one block of the depth hierarchy's level kHizTileLevel (hiz/hiz_block.glsl).
static_assert((1u << gpu::kHizTileLevel) == gpu::kPprTileSize, "ppr.reach stores the depth hierarchy of whole tiles");
static_assert(kWidths.valid(gpu::kPprTileSize * gpu::kPprTileSize, 1u) && gpu::kPprReachGroupSize % kReachThreadChoices.back() == 0,
              "ppr.reach's invocations per tile must divide the tile and the workgroup and hold the defaults");

shader::PipelineLayoutDesc reachLayout() {
    shader::PipelineLayoutDesc layout;
    layout.pushConstantBytes = sizeof(gpu::PprReachPush);
    return layout;
}
}  // namespace

PprReachPass::PprReachPass(const vk::Context& ctx)
    : ctx_(ctx),
      pipelines_(ctx, PPR_SPIRV(ppr_reach_comp), reachLayout(), "ppr.reach", kWidths),
      hierarchyPipelines_(ctx, PPR_SPIRV(ppr_reach_comp), reachLayout(), "ppr.reach", kWidths, {1u}) {}

uint32_t PprReachPass::autoThreads(const vk::DeviceInfo& device) { return kWidths.defaultFor(device); }

void PprReachPass::queueClears(graph::RenderGraph& g, TransferBatch& batch, PprReachInputs& inputs) {
    batch.emptyDispatchList(g.createBuffer("ppr.reach.args", {sizeof(gpu::TileDispatchArgs)}), false, &inputs.clearedArgs.emplace());
}

PprTileList PprReachPass::add(graph::RenderGraph& g, const FrameInputs& in, const ReflectorBinding& r, const PprReachInputs& inputs,
                              graph::ImageHandle* hierarchyWritten) const {
    const uint32_t tileCount = inputs.tilesX * inputs.tilesY;
    graph::BufferHandle clearedArgs;
    if (inputs.clearedArgs) {
        clearedArgs = *inputs.clearedArgs;
    } else {
        TransferBatch batch;
        PprReachInputs own;
        queueClears(g, batch, own);
        batch.add(g, "ppr.reach.clear");
        clearedArgs = *own.clearedArgs;
    }

    gpu::PprReachPush push{};
    push.reflectorCount = r.count;
    push.cullPlaneCount = r.cullPlanes;
    push.tilesX = inputs.tilesX;
    push.tilesY = inputs.tilesY;
    PprTileList out;
    const uint32_t lanes = pipelines_.resolve(inputs.threads);
    const bool hierarchy = inputs.hierarchy.has_value();
    if (hierarchy && !writesHierarchy(lanes)) throw std::invalid_argument("ppr.reach: the depth hierarchy is stored with one invocation per tile only");
    ComputePass pass(g, ctx_, "ppr.reach", (hierarchy ? hierarchyPipelines_ : pipelines_).get(lanes));
    pass.uniform(in.frameConstants, in.frameConstantsOffset, in.frameConstantsSize)
        .sampled(inputs.depth, in.samplers->nearestClamp)
        .hostStorage(r.reflectors)
        .storageRead(inputs.bounds)
        .hostStorage(r.planeLeaders)
        .storageReadWrite(clearedArgs, &out.args)
        .storageWrite(g.createBuffer("ppr.reach.tiles", {sizeof(gpu::PprReachedTile) * tileCount}), &out.tiles)
        .storageWrite(g.createBuffer("ppr.tile_survivors", {sizeof(uint32_t) * tileCount}), &out.tileSurvivors)
        .storageReadWrite(inputs.stats, &out.stats)
        .storageRead(inputs.visible);
    // Without the hierarchy the shader never touches binding 10: a 1x1 stand-in keeps it bound.
    if (hierarchy) pass.storageWrite(*inputs.hierarchy, hierarchyWritten);
    else pass.storageWrite(g.createImage("ppr.reach.hiz_unused", {1, 1, VK_FORMAT_R32_SFLOAT, 1}), nullptr);
    pass.push(push).dispatch(tileGroupGrid(tileCount, lanes, gpu::kPprReachGroupSize, gpu::kPprReachGroupsPerRow), gpu::kPprReachGroupSize);
    return out;
}

}  // namespace ppr::passes
