#include "ppr_bounds/ppr_bounds_pass.hpp"

#include "common/compute_pass.hpp"
#include "ppr_bounds/ppr_bounds.h"
#include "ppr_bounds_comp.h"
#include "ppr_common/tile_culling.h"

#include <algorithm>

namespace ppr::passes {

PprBoundsPass::PprBoundsPass(const vk::Context& ctx) : ctx_(ctx) {
    shader::PipelineLayoutDesc layout;
    layout.pushConstantBytes = sizeof(gpu::PprBoundsPush);
    pipeline_ = shader::createComputePipeline(ctx, PPR_SPIRV(ppr_bounds_comp), layout, "ppr.bounds");
}

graph::BufferHandle PprBoundsPass::add(graph::RenderGraph& g, const FrameInputs& in, VkBuffer reflectors, uint32_t reflectorCount) const {
    gpu::PprBoundsPush push{};
    push.reflectorCount = reflectorCount;
    const VkDeviceSize size = sizeof(gpu::PprReflectorBounds) * std::max<uint32_t>(reflectorCount, 1);
    graph::BufferHandle out;
    ComputePass(g, ctx_, "ppr.bounds", pipeline_)
        .uniform(in.frameConstants, in.frameConstantsOffset, in.frameConstantsSize)
        .hostStorage(reflectors)
        .storageWrite(g.createBuffer("ppr.reflector_bounds", {size}), &out)
        .push(push)
        .dispatch({std::max<uint32_t>(reflectorCount, 1), 1}, gpu::kPprBoundsGroupSize);
    return out;
}

}  // namespace ppr::passes
