#include "ppr_clear/ppr_clear_pass.hpp"

#include "ppr_common/encoding.h"

namespace ppr::passes {

graph::ImageHandle addPprClearPass(graph::RenderGraph& g, const std::string& name, VkExtent2D extent) {
    struct Data {
        graph::ImageHandle image;
    };
    const graph::ImageHandle created = g.createImage(name, {extent.width, extent.height, kPprIntermediateFormat, 1});
    const Data& d = g.addPass<Data>(
        "ppr.clear", graph::QueueKind::Transfer, [&](graph::PassBuilder& b, Data& data) { data.image = b.transferDst(created); },
        [](const Data& data, graph::PassContext& pc) {
            VkClearColorValue clear{};
            clear.uint32[0] = gpu::kPprClearValue;
            const VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
            vkCmdClearColorImage(pc.cmd(), pc.image(data.image), pc.layout(data.image), &clear, 1, &range);
        });
    return d.image;
}

}  // namespace ppr::passes
