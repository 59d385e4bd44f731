#include "frame/shadow_map_cache.hpp"

namespace ppr::app {
namespace {

graph::ExternalImage keptMap(const vk::Context& ctx, vk::Image& image, uint32_t resolution, VkImageUsageFlags transfer, const char* name) {
    image = vk::createImage(ctx, {resolution, resolution}, passes::ShadowPass::kFormat,
                            VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT | transfer, 1, name);
    return {image.image, image.view, {resolution, resolution, passes::ShadowPass::kFormat, 1}, {}, std::nullopt};
}

}  // namespace

graph::ImageHandle ShadowMapCache::add(graph::RenderGraph& g, const passes::FrameInputs& in, const ShadowMapKey& key, bool enabled) {
    if (!enabled) {
        release();
        return pass_.add(g, in, key.resolution);
    }
    const ShadowMapWork work = shadowMapWork(drawn_, key, animated_);
    if (work.still) {
        release();
        stillImport_ = keptMap(ctx_, still_, key.resolution, VK_IMAGE_USAGE_TRANSFER_SRC_BIT, "shadowMap.still");
        if (animated_) posedImport_ = keptMap(ctx_, posed_, key.resolution, VK_IMAGE_USAGE_TRANSFER_DST_BIT, "shadowMap.posed");
    }
    drawn_ = key;
    // The imports carry the images' layouts and last accesses from frame to frame, so a frame that
    // draws one again waits for the frames in flight that read it.
    graph::ImageHandle still = g.importImage("shadowMap.still", &stillImport_);
    if (work.still) {
        still = pass_.addInto(g, in, still, passes::ShadowPass::Casters::Still);
        ++counts_.still;
    }
    if (!animated_) return still;
    graph::ImageHandle posed = g.importImage("shadowMap.posed", &posedImport_);
    if (!work.moving) return posed;
    ++counts_.moving;
    return pass_.addInto(g, in, passes::ShadowPass::addRestore(g, still, posed), passes::ShadowPass::Casters::Moving);
}

void ShadowMapCache::release() {
    drawn_.reset();
    if (!still_.image) return;
    VK_CHECK(vkDeviceWaitIdle(ctx_.device()));
    vk::destroyImage(ctx_, still_);
    if (posed_.image) vk::destroyImage(ctx_, posed_);
    still_ = posed_ = {};
    stillImport_ = posedImport_ = {};
}

}  // namespace ppr::app
