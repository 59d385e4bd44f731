#include "pick/pick_pass.hpp"

#include "common/compute_pass.hpp"
#include "pick/pick.h"
#include "pick_comp.h"

namespace ppr::passes {

PickPass::PickPass(const vk::Context& ctx) : ctx_(ctx) {
    shader::PipelineLayoutDesc layout;
    layout.pushConstantBytes = sizeof(gpu::PickPush);
    pipeline_ = shader::createComputePipeline(ctx, PPR_SPIRV(pick_comp), layout, "pick");
}

void PickPass::add(graph::RenderGraph& g, const FrameInputs& in, const GBuffer& gb, glm::ivec2 pixel, graph::BufferHandle result) const {
    gpu::PickPush push{};
    push.pixel = pixel;
    graph::BufferHandle written;
    ComputePass(g, ctx_, "pick", pipeline_)
        .uniform(in.frameConstants, in.frameConstantsOffset, in.frameConstantsSize)
        .sampled(gb.depth, in.samplers->nearestClamp)
        .sampled(gb.normal, in.samplers->nearestClamp)
        .sampled(gb.reflector, in.samplers->nearestClamp)
        .storageWrite(result, &written)
        .push(push)
        .dispatch({1, 1}, 1);
}

}  // namespace ppr::passes
