#include "floor/floor_pass.hpp"

#include "common/compute_pass.hpp"
#include "floor_comp.h"

namespace ppr::passes {

FloorPass::FloorPass(const vk::Context& ctx) : ctx_(ctx) {
    pipeline_ = shader::createComputePipeline(ctx, PPR_SPIRV(floor_comp), {}, "floor");
}

graph::ImageHandle FloorPass::add(graph::RenderGraph& g, const FrameInputs& in, graph::ImageHandle depth, graph::ImageHandle sceneColor) const {
    graph::ImageHandle out;
    ComputePass(g, ctx_, "floor", pipeline_)
        .uniform(in.frameConstants, in.frameConstantsOffset, in.frameConstantsSize)
        .sampled(depth, in.samplers->nearestClamp)
        .sampled(sceneColor, in.samplers->nearestClamp)
        .storageWrite(g.createImage("reflection", {in.extent.width, in.extent.height, VK_FORMAT_R16G16B16A16_SFLOAT, 1}), &out)
        .dispatch(in.extent, 16);
    return out;
}

}  // namespace ppr::passes
