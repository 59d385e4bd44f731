#include "common/clear_pass.hpp"

namespace ppr::passes {

graph::ImageHandle addClearPass(graph::RenderGraph& g, const std::string& passName, graph::ImageHandle image, const VkClearColorValue& value) {
    struct Data {
        graph::ImageHandle image;
    };
    const Data& d = g.addPass<Data>(
        passName, graph::QueueKind::Transfer, [&](graph::PassBuilder& b, Data& data) { data.image = b.transferDst(image); },
        [value](const Data& data, graph::PassContext& pc) {
            const VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
            vkCmdClearColorImage(pc.cmd(), pc.image(data.image), pc.layout(data.image), &value, 1, &range);
        });
    return d.image;
}

}  // namespace ppr::passes
