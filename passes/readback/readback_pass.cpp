#include "readback/readback_pass.hpp"

#include "vk/context.hpp"

namespace ppr::passes {

void addReadbackPass(graph::RenderGraph& g, const std::string& name, graph::ImageHandle image, graph::BufferHandle buffer) {
    struct Data {
        graph::ImageHandle image;
        graph::BufferHandle buffer;
    };
    g.addPass<Data>(
        name, graph::QueueKind::Transfer,
        [&](graph::PassBuilder& b, Data& data) {
            data.image = b.transferSrc(image);
            data.buffer = b.transferDst(buffer);
            b.sideEffect();
        },
        [](const Data& data, graph::PassContext& pc) {
            const graph::ImageDesc& desc = pc.desc(data.image);
            VkBufferImageCopy region{};
            region.imageSubresource = {vk::aspectFor(desc.format), 0, 0, 1};
            region.imageExtent = {desc.width, desc.height, 1};
            vkCmdCopyImageToBuffer(pc.cmd(), pc.image(data.image), pc.layout(data.image), pc.buffer(data.buffer), 1, &region);
        });
}

}  // namespace ppr::passes
