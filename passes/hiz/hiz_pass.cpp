#include "hiz/hiz_pass.hpp"

#include "common/compute_pass.hpp"
#include "hiz/hiz.h"
#include "hiz/hiz_threads.hpp"
#include "hiz_build_comp.h"

namespace ppr::passes {

namespace {
constexpr uint32_t kCell = 1u << (gpu::kHizLevels - 1u);
constexpr WorkgroupWidths kWidths{kHizThreadChoices, gpu::kHizThreads, gpu::kHizThreadsGpu};
constexpr bool powersOfFour() {
    for (uint32_t w : kHizThreadChoices)
        if (w < 16u || (w & (w - 1u)) != 0u || (w & 0x55555555u) == 0u) return false;
    return true;
}
// At least 16: a block must stop above level 1 (hiz_build.comp's walk finishes a level-2 texel or more).
static_assert(kWidths.valid(kCell * kCell / 4u, 16u) && powersOfFour() && kHizThreadChoices.back() <= kCell * kCell / 16u,
              "hiz_threads: powers of four from 16, square blocks of at least 4x4 level-0 texels, holding the defaults");
}  // namespace

HizPass::HizPass(const vk::Context& ctx)
    : ctx_(ctx),
      pipelines_(ctx, PPR_SPIRV(hiz_build_comp), {}, "hiz.build", kWidths),
      abovePipelines_(ctx, PPR_SPIRV(hiz_build_comp), {}, "hiz.build", kWidths, {1u}) {}

uint32_t HizPass::autoThreads(const vk::DeviceInfo& device) { return kWidths.defaultFor(device); }

graph::ImageHandle HizPass::createAtlas(graph::RenderGraph& g, const FrameInputs& in) {
    const glm::uvec2 size = gpu::hizAtlasSize(gpu::hizPaddedSize({in.extent.width, in.extent.height}));
    return g.createImage("hiz.atlas", {size.x, size.y, kFormat, 1});
}

HizAtlas HizPass::add(graph::RenderGraph& g, const FrameInputs& in, graph::ImageHandle depth, uint32_t threads,
                      std::optional<graph::ImageHandle> fineLevels) const {
    const glm::uvec2 padded = gpu::hizPaddedSize({in.extent.width, in.extent.height});
    HizAtlas atlas{fineLevels ? *fineLevels : createAtlas(g, in), gpu::kHizLevels};
    // One workgroup per coarsest cell of the padded screen (its invocations: the specialization constant).
    ComputePass pass(g, ctx_, "hiz.build", (fineLevels ? abovePipelines_ : pipelines_).get(threads));
    pass.uniform(in.frameConstants, in.frameConstantsOffset, in.frameConstantsSize).sampled(depth, in.samplers->nearestClamp);
    if (fineLevels) pass.storageReadWrite(atlas.image, &atlas.image);  // the tiles' levels are read, the rest written
    else pass.storageWrite(atlas.image, &atlas.image);
    pass.dispatch({padded.x, padded.y}, kCell);
    return atlas;
}

}  // namespace ppr::passes
