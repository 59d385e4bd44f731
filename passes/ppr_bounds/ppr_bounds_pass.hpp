#pragma once
// PPR reflector bounds pass (ppr_bounds.comp): per-frame screen rectangles of the reflectors for the
// projection pass's per-tile culling.
#include "common/frame_inputs.hpp"
#include "graph/graph.hpp"

namespace ppr::passes {

class PprBoundsPass {
public:
    explicit PprBoundsPass(const vk::Context& ctx);
    // Returns "ppr.reflector_bounds" (PprReflectorBounds per reflector, at least one entry).
    graph::BufferHandle add(graph::RenderGraph& g, const FrameInputs& in, VkBuffer reflectors, uint32_t reflectorCount) const;

private:
    const vk::Context& ctx_;
    shader::Pipeline pipeline_;
};

}  // namespace ppr::passes
