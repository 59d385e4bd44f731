#include "vk/swapchain.hpp"

#include <algorithm>

namespace ppr::vk {

Swapchain::Swapchain(const Context& ctx, VkSurfaceKHR surface) : ctx_(ctx), surface_(surface) {}

Swapchain::~Swapchain() {
    vkDeviceWaitIdle(ctx_.device());
    destroyViews();
    if (swapchain_) vkDestroySwapchainKHR(ctx_.device(), swapchain_, nullptr);
}

void Swapchain::destroyViews() {
    for (VkImageView v : views_) vkDestroyImageView(ctx_.device(), v, nullptr);
    for (VkSemaphore s : renderFinished_) vkDestroySemaphore(ctx_.device(), s, nullptr);
    views_.clear();
    renderFinished_.clear();
    images_.clear();
}

bool Swapchain::recreate(VkExtent2D size, bool vsync) {
    if (size.width == 0 || size.height == 0) return false;
    vkDeviceWaitIdle(ctx_.device());
    VkSurfaceCapabilitiesKHR caps;
    VK_CHECK(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(ctx_.physicalDevice(), surface_, &caps));
    if (caps.currentExtent.width != UINT32_MAX) size = caps.currentExtent;
    size.width = std::clamp(size.width, caps.minImageExtent.width, caps.maxImageExtent.width);
    size.height = std::clamp(size.height, caps.minImageExtent.height, caps.maxImageExtent.height);
    if (size.width == 0 || size.height == 0) return false;

    uint32_t count = 0;
    vkGetPhysicalDeviceSurfaceFormatsKHR(ctx_.physicalDevice(), surface_, &count, nullptr);
    std::vector<VkSurfaceFormatKHR> formats(count);
    vkGetPhysicalDeviceSurfaceFormatsKHR(ctx_.physicalDevice(), surface_, &count, formats.data());
    // UNORM: the tonemap pass writes sRGB-encoded values itself (same bytes as a capture's PNG).
    VkSurfaceFormatKHR chosen = formats.empty() ? VkSurfaceFormatKHR{VK_FORMAT_B8G8R8A8_UNORM, VK_COLOR_SPACE_SRGB_NONLINEAR_KHR} : formats[0];
    for (auto& f : formats)
        if ((f.format == VK_FORMAT_B8G8R8A8_UNORM || f.format == VK_FORMAT_R8G8B8A8_UNORM) &&
            f.colorSpace == VK_COLOR_SPACE_SRGB_NONLINEAR_KHR) {
            chosen = f;
            break;
        }

    vkGetPhysicalDeviceSurfacePresentModesKHR(ctx_.physicalDevice(), surface_, &count, nullptr);
    std::vector<VkPresentModeKHR> modes(count);
    vkGetPhysicalDeviceSurfacePresentModesKHR(ctx_.physicalDevice(), surface_, &count, modes.data());
    VkPresentModeKHR mode = VK_PRESENT_MODE_FIFO_KHR;
    if (!vsync) {
        for (VkPresentModeKHR m : modes)
            if (m == VK_PRESENT_MODE_MAILBOX_KHR || m == VK_PRESENT_MODE_IMMEDIATE_KHR) {
                mode = m;
                if (m == VK_PRESENT_MODE_IMMEDIATE_KHR) break;
            }
    }

    uint32_t imageCount = std::max(caps.minImageCount + 1, 3u);
    if (caps.maxImageCount) imageCount = std::min(imageCount, caps.maxImageCount);

    VkSwapchainCreateInfoKHR sci{VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR};
    sci.surface = surface_;
    sci.minImageCount = imageCount;
    sci.imageFormat = chosen.format;
    sci.imageColorSpace = chosen.colorSpace;
    sci.imageExtent = size;
    sci.imageArrayLayers = 1;
    sci.imageUsage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
    sci.imageSharingMode = VK_SHARING_MODE_EXCLUSIVE;
    sci.preTransform = caps.currentTransform;
    sci.compositeAlpha = VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR;
    sci.presentMode = mode;
    sci.clipped = VK_TRUE;
    VkSwapchainKHR old = swapchain_;
    sci.oldSwapchain = old;
    VK_CHECK(vkCreateSwapchainKHR(ctx_.device(), &sci, nullptr, &swapchain_));
    destroyViews();
    if (old) vkDestroySwapchainKHR(ctx_.device(), old, nullptr);

    format_ = chosen.format;
    extent_ = size;
    vsync_ = vsync;
    vkGetSwapchainImagesKHR(ctx_.device(), swapchain_, &count, nullptr);
    images_.resize(count);
    vkGetSwapchainImagesKHR(ctx_.device(), swapchain_, &count, images_.data());
    for (uint32_t i = 0; i < count; ++i) {
        VkImageViewCreateInfo vci{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
        vci.image = images_[i];
        vci.viewType = VK_IMAGE_VIEW_TYPE_2D;
        vci.format = format_;
        vci.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
        VkImageView view;
        VK_CHECK(vkCreateImageView(ctx_.device(), &vci, nullptr, &view));
        views_.push_back(view);
        VkSemaphoreCreateInfo semInfo{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
        VkSemaphore sem;
        VK_CHECK(vkCreateSemaphore(ctx_.device(), &semInfo, nullptr, &sem));
        renderFinished_.push_back(sem);
        ctx_.name(images_[i], VK_OBJECT_TYPE_IMAGE, "swapchain image " + std::to_string(i));
        ctx_.name(view, VK_OBJECT_TYPE_IMAGE_VIEW, "swapchain view " + std::to_string(i));
        ctx_.name(sem, VK_OBJECT_TYPE_SEMAPHORE, "render finished " + std::to_string(i));
    }
    return true;
}

}  // namespace ppr::vk
