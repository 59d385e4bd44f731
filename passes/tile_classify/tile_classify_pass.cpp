#include "tile_classify/tile_classify_pass.hpp"

#include "common/compute_pass.hpp"
#include "common/dispatch_args.hpp"
#include "common/tile_group_grid.hpp"
#include "common/transfer_batch.hpp"
#include "ppr_common/tiles.h"
#include "tile_classify/tile_classify.h"
#include "tile_classify_comp.h"

#include <array>
#include <cstddef>

namespace ppr::passes {

namespace {
constexpr WorkgroupWidths kWidths{kClassifyThreadChoices, gpu::kTileClassifyThreads, gpu::kTileClassifyThreadsGpu};

static_assert(kWidths.valid(gpu::kPprTileSize * gpu::kPprTileSize / 4u, 1u) && gpu::kTileClassifyGroupSize % kClassifyThreadChoices.back() == 0,
              "tiles.classify's invocations per tile must divide the tile's quads and the workgroup and hold the defaults");


shader::PipelineLayoutDesc classifyLayout() {
    shader::PipelineLayoutDesc layout;
    layout.pushConstantBytes = sizeof(gpu::TileClassifyPush);
    return layout;
}
}  // namespace

TileClassifyPass::TileClassifyPass(const vk::Context& ctx)
    : ctx_(ctx), pipelines_(ctx, PPR_SPIRV(tile_classify_comp), classifyLayout(), "tiles.classify", kWidths) {}

uint32_t TileClassifyPass::autoThreads(const vk::DeviceInfo& device) { return kWidths.defaultFor(device); }

void TileClassifyPass::queueClears(graph::RenderGraph& g, TransferBatch& batch, graph::BufferHandle stats, TileClassifyTargets* cleared) {
    // Empty lists (x = 0, y = z = 1) and zero counters.
    static constexpr std::array<gpu::TileDispatchArgs, gpu::kTileClassCount> kEmpty = [] {
        std::array<gpu::TileDispatchArgs, gpu::kTileClassCount> empty{};
        for (gpu::TileDispatchArgs& a : empty) a = {0u, 1u, 1u};
        return empty;
    }();
    batch.writeBuffer(g.createBuffer("tiles.args", {sizeof(kEmpty)}), kEmpty.data(), sizeof(kEmpty), false, &cleared->args);
    batch.writeBuffer(stats, nullptr, 0, true, &cleared->stats);
}

TileLists TileClassifyPass::add(graph::RenderGraph& g, const FrameInputs& in, const GBuffer& gb, graph::BufferHandle stats,
                                uint32_t maxReflectorId, uint32_t threads) const {
    TransferBatch batch;
    TileClassifyTargets cleared;
    queueClears(g, batch, stats, &cleared);
    batch.add(g, "tiles.clear");
    return add(g, in, gb, cleared, maxReflectorId, threads);
}

TileLists TileClassifyPass::add(graph::RenderGraph& g, const FrameInputs& in, const GBuffer& gb, const TileClassifyTargets& cleared,
                                uint32_t maxReflectorId, uint32_t threads) const {
    TileLists t;
    t.tilesX = gpu::pprTilesCovering(in.extent.width);
    t.tilesY = gpu::pprTilesCovering(in.extent.height);
    graph::BufferHandle lists = g.createBuffer("tiles.lists", {sizeof(uint32_t) * gpu::kTileClassCount * t.tileCount()});

    gpu::TileClassifyPush push{};
    push.tilesX = t.tilesX;
    push.tileCount = t.tileCount();
    push.maxReflectorId = maxReflectorId;
    ComputePass(g, ctx_, "tiles.classify", pipelines_.get(threads))
        .uniform(in.frameConstants, in.frameConstantsOffset, in.frameConstantsSize)
        .sampled(gb.reflector, in.samplers->nearestClamp)
        .sampled(gb.material, in.samplers->nearestClamp)
        .storageReadWrite(cleared.args, &t.args)
        .storageWrite(lists, &t.lists)
        .push(push)
        .dispatch(tileGroupGrid(t.tileCount(), pipelines_.resolve(threads), gpu::kTileClassifyGroupSize, gpu::kTileClassifyGroupsPerRow),
                  gpu::kTileClassifyGroupSize);

    // The arguments as the dispatches will read them, into the host-visible stats.
    t.stats = addCountCopy(g, "tiles.count", t.args, 0, cleared.stats, offsetof(gpu::PprFrameStats, dispatch), sizeof(gpu::PprFrameStats::dispatch));
    return t;
}

}  // namespace ppr::passes
