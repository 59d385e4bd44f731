#include "ppr_bounds/ppr_bounds_pass.hpp"

#include "common/compute_pass.hpp"
#include "ppr_bounds/ppr_bounds.h"
#include "ppr_bounds_comp.h"
#include "ppr_common/tile_culling.h"
#include "ppr_common/tiles.h"

#include <algorithm>

namespace ppr::passes {

// Each invocation's run of the projection order fits one 32-bit mask, and the scanned counts 16 bits.
static_assert(gpu::kPprMaxReflectors <= 32u * gpu::kPprBoundsGroupSize && gpu::kPprMaxReflectors < 0x10000u,
              "ppr.bounds compacts every reflector in one workgroup");
static_assert(gpu::kPprMaxReflectors % gpu::kPprBoundsGroupSize == 0u, "a run's rectangles fit the shader's array");
static_assert(gpu::kPprCullChunkCount * gpu::kPprCullChunk == gpu::kPprMaxReflectors, "a chunk summary for every run of candidates");
static_assert(gpu::kPprVisibleListsOffset == sizeof(gpu::PprVisibleCounts) + 2 * gpu::kPprCullChunkCount * sizeof(gpu::PprCullChunk) +
                                                 gpu::kPprMaxCullPlanes * sizeof(gpu::PprCullPlaneBounds),
              "PPR_VISIBLE_REFLECTORS's layout");

PprBoundsPass::PprBoundsPass(const vk::Context& ctx) : ctx_(ctx) {
    shader::PipelineLayoutDesc layout;
    layout.pushConstantBytes = sizeof(gpu::PprBoundsPush);
    pipeline_ = shader::createComputePipeline(ctx, PPR_SPIRV(ppr_bounds_comp), layout, "ppr.bounds");
}

PprBoundsOutputs PprBoundsPass::add(graph::RenderGraph& g, const FrameInputs& in, const ReflectorBinding& r, graph::BufferHandle stats) const {
    gpu::PprBoundsPush push{};
    push.reflectorCount = r.count;
    push.cullPlaneCount = r.cullPlanes;
    const VkDeviceSize entries = std::max<uint32_t>(r.count, 1);
    PprBoundsOutputs out;
    ComputePass(g, ctx_, "ppr.bounds", pipeline_)
        .uniform(in.frameConstants, in.frameConstantsOffset, in.frameConstantsSize)
        .hostStorage(r.reflectors)
        .storageWrite(g.createBuffer("ppr.reflector_bounds", {sizeof(gpu::PprReflectorBounds) * entries}), &out.bounds)
        .hostStorage(r.order)
        .storageWrite(g.createBuffer("ppr.visible_reflectors", {gpu::kPprVisibleListsOffset + 2 * sizeof(uint32_t) * entries}),
                      &out.visible)
        .storageReadWrite(stats, &out.stats)
        .push(push)
        .dispatch({gpu::kPprBoundsGroupSize, 1}, gpu::kPprBoundsGroupSize);
    return out;
}

}  // namespace ppr::passes
