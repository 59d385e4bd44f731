#pragma once
// PPR reach pass (ppr_reach.comp): the tiles the projection pass is dispatched on when per-tile
// culling and indirect dispatch are on — those whose mirror image can land on a reflector at all.
#include "common/frame_inputs.hpp"
#include "common/workgroup_widths.hpp"
#include "graph/graph.hpp"
#include "ppr_project/ppr_project_pass.hpp"
#include "ppr_reach/reach_threads.hpp"

namespace ppr::passes {

struct PprReachInputs {
    graph::ImageHandle depth;
    graph::BufferHandle bounds;   // ppr.bounds outputs: the rectangles
    graph::BufferHandle visible;  // and the reflectors on screen
    graph::BufferHandle stats;   // PprFrameStats (tilesWithContent added to)
    uint32_t tilesX = 0, tilesY = 0;
    uint32_t threads = 0;  // invocations per tile, one of kReachThreadChoices; 0: autoThreads
};

class PprReachPass {
public:
    explicit PprReachPass(const vk::Context& ctx);
    // Clears the arguments ("ppr.reach.clear", transfer) and lists the reachable tiles ("ppr.reach").
    PprTileList add(graph::RenderGraph& g, const FrameInputs& in, const ReflectorBinding& reflectors, const PprReachInputs& inputs) const;
    // What threads = 0 means on this device: kPprReachThreads on a CPU, kPprReachThreadsGpu elsewhere.
    static uint32_t autoThreads(const vk::DeviceInfo& device);

private:
    const vk::Context& ctx_;
    WidthPipelines pipelines_;
};

}  // namespace ppr::passes
