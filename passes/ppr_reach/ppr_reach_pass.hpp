#pragma once
// PPR reach pass (ppr_reach.comp): the tiles the projection pass is dispatched on when per-tile
// culling and indirect dispatch are on — those whose mirror image can land on a reflector at all.
#include "common/frame_inputs.hpp"
#include "common/transfer_batch.hpp"
#include "common/workgroup_widths.hpp"
#include "graph/graph.hpp"
#include "ppr_project/ppr_project_pass.hpp"
#include "ppr_reach/reach_threads.hpp"

#include <optional>

namespace ppr::passes {

struct PprReachInputs {
    graph::ImageHandle depth;
    graph::BufferHandle bounds;   // ppr.bounds outputs: the rectangles
    graph::BufferHandle visible;  // and the reflectors on screen
    graph::BufferHandle stats;   // PprFrameStats (tilesWithContent added to)
    uint32_t tilesX = 0, tilesY = 0;
    uint32_t threads = 0;  // invocations per tile, one of kReachThreadChoices; 0: autoThreads
    // The depth hierarchy's atlas (hiz/hiz.h), when a fallback will march it and the pass runs one
    // invocation per tile (writesHierarchy): levels 1..kHizTileLevel of every tile are stored into it
    // from the gathers the boxes take, and HizPass adds the levels above.
    std::optional<graph::ImageHandle> hierarchy;
    // The dispatch arguments as an empty list, cleared in a technique's batch (queueClears); unset:
    // add() clears them in a pass of its own, "ppr.reach.clear".
    std::optional<graph::BufferHandle> clearedArgs;
};

class PprReachPass {
public:
    explicit PprReachPass(const vk::Context& ctx);
    // Clears the arguments ("ppr.reach.clear", transfer; unless inputs.clearedArgs) and lists the
    // reachable tiles ("ppr.reach").
    // With inputs.hierarchy, `hierarchyWritten` gets the atlas as written.
    PprTileList add(graph::RenderGraph& g, const FrameInputs& in, const ReflectorBinding& reflectors, const PprReachInputs& inputs,
                    graph::ImageHandle* hierarchyWritten = nullptr) const;
    // Whether the pass run with `threads` invocations per tile (0: autoThreads) can store the depth
    // hierarchy's tile levels: with one invocation per tile, which walks the tile's quads alone.
    bool writesHierarchy(uint32_t threads) const { return pipelines_.resolve(threads) == 1u; }
    // What threads = 0 means on this device: kPprReachThreads on a CPU, kPprReachThreadsGpu elsewhere.
    static uint32_t autoThreads(const vk::DeviceInfo& device);
    // Creates the arguments and queues their clear in `batch`: inputs.clearedArgs after batch.add().
    static void queueClears(graph::RenderGraph& g, TransferBatch& batch, PprReachInputs& inputs);

private:
    const vk::Context& ctx_;
    WidthPipelines pipelines_;
    WidthPipelines hierarchyPipelines_;  // kWritesHierarchy
};

}  // namespace ppr::passes
