#pragma once
// Swapchain for the windowed path: recreated on resize (and skipped while minimised, extent 0).
#include "vk/context.hpp"

#include <vector>

namespace ppr::vk {

class Swapchain {
public:
    Swapchain(const Context& ctx, VkSurfaceKHR surface);
    ~Swapchain();
    Swapchain(const Swapchain&) = delete;
    Swapchain& operator=(const Swapchain&) = delete;

    // (Re)creates for the given framebuffer size; returns false when the size is zero (minimised).
    bool recreate(VkExtent2D framebufferSize, bool vsync);

    VkSwapchainKHR handle() const { return swapchain_; }
    VkFormat format() const { return format_; }
    VkExtent2D extent() const { return extent_; }
    uint32_t imageCount() const { return static_cast<uint32_t>(images_.size()); }
    VkImage image(uint32_t i) const { return images_[i]; }
    VkImageView view(uint32_t i) const { return views_[i]; }
    // Signalled by rendering into image i, waited by present (one per image, so reuse is safe).
    VkSemaphore renderFinished(uint32_t i) const { return renderFinished_[i]; }
    bool vsync() const { return vsync_; }

private:
    void destroyViews();
    const Context& ctx_;
    VkSurfaceKHR surface_;
    VkSwapchainKHR swapchain_ = VK_NULL_HANDLE;
    VkFormat format_ = VK_FORMAT_UNDEFINED;
    VkExtent2D extent_{};
    bool vsync_ = true;
    std::vector<VkImage> images_;
    std::vector<VkImageView> views_;
    std::vector<VkSemaphore> renderFinished_;
};

}  // namespace ppr::vk
