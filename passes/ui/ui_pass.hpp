#pragma once
// Overlay pass drawn on top of the final image inside its own VkRenderPass: the ImGui 1.86 Vulkan
// backend cannot use dynamic rendering, so this pass declares customRendering() and begins a render
// pass (LOAD/STORE, COLOR_ATTACHMENT_OPTIMAL in and out, explicit external dependencies) over a
// framebuffer cached per image view. The graph still places every barrier around it.
//
// The pass does not depend on ImGui itself: the viewer hands it a `Draw` callback (which calls
// ImGui_ImplVulkan_RenderDrawData), so ppr_passes stays free of UI libraries.
#include "graph/graph.hpp"
#include "vk/context.hpp"

#include <functional>
#include <map>

namespace ppr::passes {

class UiPass {
public:
    using Draw = std::function<void(VkCommandBuffer)>;

    explicit UiPass(const vk::Context& ctx) : ctx_(ctx) {}
    ~UiPass();
    UiPass(const UiPass&) = delete;
    UiPass& operator=(const UiPass&) = delete;

    // The render pass for a target format, created on first request (not on the hot path).
    VkRenderPass renderPass(VkFormat format);
    // Destroys the cached framebuffers. Call with the device idle whenever the image views they
    // reference go away (swapchain recreation).
    void releaseFramebuffers();
    size_t framebufferCount() const { return framebuffers_.size(); }

    // Adds the "ui" pass drawing `draw` over `target`; returns the new version of target.
    // renderPass(format of target) must have been created beforehand.
    graph::ImageHandle add(graph::RenderGraph& g, graph::ImageHandle target, Draw draw);

private:
    struct Framebuffer {
        VkFramebuffer framebuffer = VK_NULL_HANDLE;
        VkRenderPass renderPass = VK_NULL_HANDLE;
        VkExtent2D extent{};
    };
    VkFramebuffer framebuffer(VkImageView view, VkRenderPass renderPass, VkExtent2D extent);

    const vk::Context& ctx_;
    std::map<VkFormat, VkRenderPass> renderPasses_;
    std::map<VkImageView, Framebuffer> framebuffers_;
};

}  // namespace ppr::passes
