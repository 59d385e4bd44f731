// The GPU allocator behind GraphExecutor::history(): VMA images and buffers via engine/vk.
#include "graph/history.hpp"
#include "vk/context.hpp"

#include <memory>
#include <unordered_map>

namespace ppr::graph {

namespace {

// Transients get exactly the usage their declared accesses need, but a history pair is created before
// (and outlives) any one frame's declarations: imports do not derive usage. So it gets every usage a
// temporal pass may plausibly ask for, minus what the format cannot do (sRGB has no storage, depth no
// color attachment), which would otherwise make vkCreateImage invalid.
VkImageUsageFlags historyImageUsage(const vk::Context& ctx, VkFormat format) {
    VkFormatProperties props{};
    vkGetPhysicalDeviceFormatProperties(ctx.physicalDevice(), format, &props);
    const VkFormatFeatureFlags f = props.optimalTilingFeatures;
    VkImageUsageFlags usage = VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    if (f & VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT) usage |= VK_IMAGE_USAGE_SAMPLED_BIT;
    if (f & VK_FORMAT_FEATURE_STORAGE_IMAGE_BIT) usage |= VK_IMAGE_USAGE_STORAGE_BIT;
    if (f & VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BIT) usage |= VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT;
    if (f & VK_FORMAT_FEATURE_DEPTH_STENCIL_ATTACHMENT_BIT) usage |= VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT;
    return usage;
}

// Same reasoning for buffers: storage (compute reads/writes) and transfer (clears, copies, read-back).
constexpr VkBufferUsageFlags kHistoryBufferUsage =
    VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;

}  // namespace

HistoryAllocator vkHistoryAllocator(const vk::Context& ctx) {
    // The store only keeps VkImage/VkBuffer handles; the VMA allocations they need to be freed live
    // here, shared by the four closures.
    struct Owned {
        std::unordered_map<VkImage, vk::Image> images;
        std::unordered_map<VkBuffer, vk::Buffer> buffers;
    };
    auto owned = std::make_shared<Owned>();
    const vk::Context* c = &ctx;
    HistoryAllocator a;
    a.createImage = [c, owned](const std::string& name, const ImageDesc& d) {
        vk::Image img = vk::createImage(*c, {d.width, d.height}, d.format, historyImageUsage(*c, d.format), d.mipLevels,
                                        "history:" + name);
        owned->images[img.image] = img;
        ExternalImage e;
        e.image = img.image;
        e.view = img.view;
        return e;
    };
    // Frees happen only on resize / format change and at teardown; a frame in flight may still use the
    // memory, and waiting for the device there is simpler than tracking which frame used it last.
    a.destroyImage = [c, owned](const ExternalImage& e) {
        auto it = owned->images.find(e.image);
        if (it == owned->images.end()) return;
        VK_CHECK(vkDeviceWaitIdle(c->device()));
        vk::destroyImage(*c, it->second);
        owned->images.erase(it);
    };
    a.createBuffer = [c, owned](const std::string& name, const BufferDesc& d) {
        vk::Buffer buf = vk::createBuffer(*c, d.size, kHistoryBufferUsage, vk::MemoryUse::GpuOnly, "history:" + name);
        owned->buffers[buf.buffer] = buf;
        ExternalBuffer e;
        e.buffer = buf.buffer;
        return e;
    };
    a.destroyBuffer = [c, owned](const ExternalBuffer& e) {
        auto it = owned->buffers.find(e.buffer);
        if (it == owned->buffers.end()) return;
        VK_CHECK(vkDeviceWaitIdle(c->device()));
        vk::destroyBuffer(*c, it->second);
        owned->buffers.erase(it);
    };
    return a;
}

}  // namespace ppr::graph
