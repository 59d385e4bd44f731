#include "hiz/hiz_pass.hpp"

#include "common/compute_pass.hpp"
#include "hiz/hiz.h"
#include "hiz_build_comp.h"

namespace ppr::passes {

HizPass::HizPass(const vk::Context& ctx) : ctx_(ctx) {
    shader::PipelineLayoutDesc layout;
    layout.pushConstantBytes = sizeof(gpu::HizBuildPush);
    pipeline_ = shader::createComputePipeline(ctx, PPR_SPIRV(hiz_build_comp), layout, "hiz.build");
}

HizAtlas HizPass::add(graph::RenderGraph& g, const FrameInputs& in, graph::ImageHandle depth) const {
    const glm::uvec2 padded = gpu::hizPaddedSize({in.extent.width, in.extent.height});
    const glm::uvec2 size = gpu::hizAtlasSize(padded);
    HizAtlas atlas{g.createImage("hiz.atlas", {size.x, size.y, kFormat, 1}), gpu::kHizLevels};
    for (uint32_t level = 1; level < gpu::kHizLevels; ++level) {
        gpu::HizBuildPush push{};
        push.level = level;
        push.dstOrigin = gpu::hizLevelOrigin(padded, level);
        push.dstSize = gpu::hizLevelSize(padded, level);
        if (level > 1) push.srcOrigin = gpu::hizLevelOrigin(padded, level - 1);
        ComputePass pass(g, ctx_, "hiz.build." + std::to_string(level), pipeline_);
        pass.uniform(in.frameConstants, in.frameConstantsOffset, in.frameConstantsSize).sampled(depth, in.samplers->nearestClamp);
        // Level 1 (from the depth buffer) starts the image; later levels read the one below and keep the rest.
        if (level == 1) pass.storageWrite(atlas.image, &atlas.image);
        else pass.storageReadWrite(atlas.image, &atlas.image);
        pass.push(push).dispatch({push.dstSize.x, push.dstSize.y}, gpu::kHizGroupSize);
    }
    return atlas;
}

}  // namespace ppr::passes
