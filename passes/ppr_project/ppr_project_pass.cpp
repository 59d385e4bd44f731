#include "ppr_project/ppr_project_pass.hpp"

#include "common/compute_pass.hpp"
#include "ppr_project/ppr_project.h"
#include "ppr_project_comp.h"

namespace ppr::passes {

PprProjectPass::PprProjectPass(const vk::Context& ctx) : ctx_(ctx) {
    shader::PipelineLayoutDesc layout;
    layout.pushBindings = {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
                           VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE};
    layout.pushConstantBytes = sizeof(gpu::PprProjectPush);
    pipeline_ = shader::createComputePipeline(ctx, PPR_SPIRV(ppr_project_comp), layout, "ppr.project");
}

graph::ImageHandle PprProjectPass::add(graph::RenderGraph& g, const FrameInputs& in, graph::ImageHandle depth, const ReflectorBinding& r,
                                       graph::ImageHandle intermediate) const {
    gpu::PprProjectPush push{};
    push.reflectorCount = r.count;
    graph::ImageHandle out;
    ComputePass(g, ctx_, "ppr.project", pipeline_)
        .uniform(in.frameConstants, in.frameConstantsOffset, in.frameConstantsSize)
        .sampled(depth, in.samplers->nearestClamp)
        .hostStorage(r.reflectors)
        .hostStorage(r.order)
        .storageReadWrite(intermediate, &out)
        .push(push)
        .dispatch(in.extent, gpu::kPprProjectGroupSize);
    return out;
}

}  // namespace ppr::passes
