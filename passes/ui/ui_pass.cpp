#include "ui/ui_pass.hpp"

#include <stdexcept>
#include <string>

namespace ppr::passes {

UiPass::~UiPass() {
    releaseFramebuffers();
    for (auto& [format, rp] : renderPasses_) vkDestroyRenderPass(ctx_.device(), rp, nullptr);
}

VkRenderPass UiPass::renderPass(VkFormat format) {
    if (auto it = renderPasses_.find(format); it != renderPasses_.end()) return it->second;

    VkAttachmentDescription color{};
    color.format = format;
    color.samples = VK_SAMPLE_COUNT_1_BIT;
    color.loadOp = VK_ATTACHMENT_LOAD_OP_LOAD;  // draw over the tonemapped image
    color.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    color.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
    color.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    // The graph transitions the image to COLOR_ATTACHMENT_OPTIMAL before the pass and away after it.
    color.initialLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    color.finalLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;

    VkAttachmentReference ref{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
    VkSubpassDescription subpass{};
    subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
    subpass.colorAttachmentCount = 1;
    subpass.pColorAttachments = &ref;

    // Explicit dependencies (instead of the implicit ones) so the render pass chains with the graph's
    // barriers on COLOR_ATTACHMENT_OUTPUT on both sides.
    VkSubpassDependency deps[2]{};
    deps[0].srcSubpass = VK_SUBPASS_EXTERNAL;
    deps[0].dstSubpass = 0;
    deps[0].srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
    deps[0].dstStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
    deps[0].srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
    deps[0].dstAccessMask = VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
    deps[1].srcSubpass = 0;
    deps[1].dstSubpass = VK_SUBPASS_EXTERNAL;
    deps[1].srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
    deps[1].dstStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
    deps[1].srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
    deps[1].dstAccessMask = VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;

    VkRenderPassCreateInfo ci{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
    ci.attachmentCount = 1;
    ci.pAttachments = &color;
    ci.subpassCount = 1;
    ci.pSubpasses = &subpass;
    ci.dependencyCount = 2;
    ci.pDependencies = deps;
    VkRenderPass rp = VK_NULL_HANDLE;
    VK_CHECK(vkCreateRenderPass(ctx_.device(), &ci, nullptr, &rp));
    ctx_.name(rp, VK_OBJECT_TYPE_RENDER_PASS, "ui render pass (format " + std::to_string(format) + ")");
    renderPasses_.emplace(format, rp);
    return rp;
}

void UiPass::releaseFramebuffers() {
    for (auto& [view, fb] : framebuffers_) vkDestroyFramebuffer(ctx_.device(), fb.framebuffer, nullptr);
    framebuffers_.clear();
}

VkFramebuffer UiPass::framebuffer(VkImageView view, VkRenderPass renderPass, VkExtent2D extent) {
    if (auto it = framebuffers_.find(view); it != framebuffers_.end()) {
        const Framebuffer& fb = it->second;
        if (fb.renderPass != renderPass || fb.extent.width != extent.width || fb.extent.height != extent.height)
            throw std::logic_error("ui pass: cached framebuffer does not match its image view any more "
                                   "(releaseFramebuffers() was not called after the swapchain was recreated)");
        return fb.framebuffer;
    }
    VkFramebufferCreateInfo ci{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
    ci.renderPass = renderPass;
    ci.attachmentCount = 1;
    ci.pAttachments = &view;
    ci.width = extent.width;
    ci.height = extent.height;
    ci.layers = 1;
    Framebuffer fb{VK_NULL_HANDLE, renderPass, extent};
    VK_CHECK(vkCreateFramebuffer(ctx_.device(), &ci, nullptr, &fb.framebuffer));
    ctx_.name(fb.framebuffer, VK_OBJECT_TYPE_FRAMEBUFFER, "ui framebuffer " + std::to_string(framebuffers_.size()));
    framebuffers_.emplace(view, fb);
    return fb.framebuffer;
}

graph::ImageHandle UiPass::add(graph::RenderGraph& g, graph::ImageHandle target, Draw draw) {
    struct Data {
        graph::ImageHandle target;
    };
    const Data& d = g.addPass<Data>(
        "ui", graph::QueueKind::Graphics,
        [&](graph::PassBuilder& b, Data& data) {
            data.target = b.colorAttachment(target, graph::LoadOp::Load);
            b.customRendering();
            b.sideEffect();
        },
        [this, draw = std::move(draw)](const Data& data, graph::PassContext& pc) {
            const graph::ImageDesc& desc = pc.desc(data.target);
            auto it = renderPasses_.find(desc.format);
            if (it == renderPasses_.end()) throw std::logic_error("ui pass: renderPass() was not created for the target format");
            const VkExtent2D extent{desc.width, desc.height};
            VkRenderPassBeginInfo bi{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
            bi.renderPass = it->second;
            bi.framebuffer = framebuffer(pc.view(data.target), it->second, extent);
            bi.renderArea = {{0, 0}, extent};
            VkCommandBuffer cmd = pc.cmd();
            vkCmdBeginRenderPass(cmd, &bi, VK_SUBPASS_CONTENTS_INLINE);
            if (draw) draw(cmd);
            vkCmdEndRenderPass(cmd);
        });
    return d.target;
}

}  // namespace ppr::passes
