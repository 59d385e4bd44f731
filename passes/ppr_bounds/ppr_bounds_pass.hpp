#pragma once
// PPR reflector bounds pass (ppr_bounds.comp): per-frame screen rectangles of the reflectors, and the
// reflectors on screen compacted in projection order, for the projection pass's per-tile culling
// and the reach pass.
#include "common/frame_inputs.hpp"
#include "graph/graph.hpp"
#include "ppr_project/ppr_project_pass.hpp"

namespace ppr::passes {

struct PprBoundsOutputs {
    graph::BufferHandle bounds;   // "ppr.reflector_bounds": PprReflectorBounds per reflector (at least one entry)
    graph::BufferHandle visible;  // "ppr.visible_reflectors": PprVisibleCounts, the chunk summaries, then the two lists (tile_culling.h)
    graph::BufferHandle stats;    // PprFrameStats with the two counts written
};

class PprBoundsPass {
public:
    explicit PprBoundsPass(const vk::Context& ctx);
    PprBoundsOutputs add(graph::RenderGraph& g, const FrameInputs& in, const ReflectorBinding& reflectors, graph::BufferHandle stats) const;

private:
    const vk::Context& ctx_;
    shader::Pipeline pipeline_;
};

}  // namespace ppr::passes
