#pragma once
// Tile classification (tile_classify.comp): per-class tile lists and their indirect dispatch
// arguments, all graph buffers, plus the frame's tile counts in the stats buffer.
#include "common/frame_inputs.hpp"
#include "common/transfer_batch.hpp"
#include "common/workgroup_widths.hpp"
#include "gbuffer/gbuffer_pass.hpp"
#include "graph/graph.hpp"
#include "tile_classify/classify_threads.hpp"

namespace ppr::passes {

struct TileLists {
    graph::BufferHandle args;   // TileDispatchArgs[kTileClassCount] (ppr_common/tiles.h)
    graph::BufferHandle lists;  // uint[kTileClassCount * tileCount]: class c's list from c * tileCount
    graph::BufferHandle stats;  // PprFrameStats, new version
    uint32_t tilesX = 0, tilesY = 0;
    uint32_t tileCount() const { return tilesX * tilesY; }
};

// The arguments and the stats, cleared (TileClassifyPass::queueClears).
struct TileClassifyTargets {
    graph::BufferHandle args;   // TileDispatchArgs[kTileClassCount], every list empty
    graph::BufferHandle stats;  // PprFrameStats, zero
};

class TileClassifyPass {
public:
    explicit TileClassifyPass(const vk::Context& ctx);
    // Clears the arguments and `stats` ("tiles.clear", transfer), classifies ("tiles.classify") and
    // copies the arguments into `stats` ("tiles.count").
    // Reflector ids above maxReflectorId do not make a tile planar (beyond PPR's budget). `threads`:
    // invocations per tile, one of kClassifyThreadChoices, or 0 for the device's default.
    TileLists add(graph::RenderGraph& g, const FrameInputs& in, const GBuffer& gb, graph::BufferHandle stats, uint32_t maxReflectorId,
                  uint32_t threads) const;
    // The same with the clears queued in a technique's batch (queueClears; "tiles.clear" is not added).
    TileLists add(graph::RenderGraph& g, const FrameInputs& in, const GBuffer& gb, const TileClassifyTargets& cleared,
                  uint32_t maxReflectorId, uint32_t threads) const;
    // Creates the arguments and queues their clear and the stats' in `batch`: `cleared` after batch.add().
    static void queueClears(graph::RenderGraph& g, TransferBatch& batch, graph::BufferHandle stats, TileClassifyTargets* cleared);
    // What threads = 0 means on this device: kTileClassifyThreads on a CPU, kTileClassifyThreadsGpu elsewhere.
    static uint32_t autoThreads(const vk::DeviceInfo& device);

private:
    const vk::Context& ctx_;
    WidthPipelines pipelines_;
};

}  // namespace ppr::passes
