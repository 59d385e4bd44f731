#include "ppr_reflect/ppr_reflect_pass.hpp"

#include "common/compute_pass.hpp"
#include "ppr_reflect/ppr_reflect.h"
#include "ppr_reflect_comp.h"

namespace ppr::passes {

PprReflectPass::PprReflectPass(const vk::Context& ctx) : ctx_(ctx) {
    shader::PipelineLayoutDesc layout;
    layout.pushBindings = {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER,         VK_DESCRIPTOR_TYPE_STORAGE_IMAGE,
                           VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
                           VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE};
    layout.pushConstantBytes = sizeof(gpu::PprReflectPush);
    pipeline_ = shader::createComputePipeline(ctx, PPR_SPIRV(ppr_reflect_comp), layout, "ppr.reflect");
}

graph::ImageHandle PprReflectPass::add(graph::RenderGraph& g, const FrameInputs& in, graph::ImageHandle intermediate,
                                       graph::ImageHandle sceneColor, graph::ImageHandle reflectorIds, uint32_t flags,
                                       uint32_t debugView) const {
    gpu::PprReflectPush push{};
    push.flags = flags;
    push.debugView = debugView;
    graph::ImageHandle out;
    ComputePass(g, ctx_, "ppr.reflect", pipeline_)
        .uniform(in.frameConstants, in.frameConstantsOffset, in.frameConstantsSize)
        .storageRead(intermediate)
        .sampled(sceneColor, in.samplers->linearClamp)
        .sampled(sceneColor, in.samplers->nearestClamp)
        .sampled(reflectorIds, in.samplers->nearestClamp)
        .storageWrite(g.createImage("reflection", {in.extent.width, in.extent.height, kReflectionFormat, 1}), &out)
        .push(push)
        .dispatch(in.extent, gpu::kPprReflectGroupSize);
    return out;
}

}  // namespace ppr::passes
