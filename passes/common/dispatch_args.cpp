#include "common/dispatch_args.hpp"

#include "common/transfer_batch.hpp"

namespace ppr::passes {

graph::BufferHandle addEmptyDispatchList(graph::RenderGraph& g, const std::string& passName, graph::BufferHandle buffer, bool zeroRest) {
    TransferBatch batch;
    graph::BufferHandle cleared;
    batch.emptyDispatchList(buffer, zeroRest, &cleared);
    batch.add(g, passName);
    return cleared;
}

graph::BufferHandle addCountCopy(graph::RenderGraph& g, const std::string& passName, graph::BufferHandle src, VkDeviceSize srcOffset,
                                 graph::BufferHandle dst, VkDeviceSize dstOffset, VkDeviceSize size) {
    struct Copy {
        graph::BufferHandle src, dst;
    };
    return g
        .addPass<Copy>(
            passName, graph::QueueKind::Transfer,
            [&](graph::PassBuilder& b, Copy& d) {
                d.src = b.transferSrc(src);
                d.dst = b.transferDst(dst);
            },
            [srcOffset, dstOffset, size](const Copy& d, graph::PassContext& pc) {
                const VkBufferCopy region{srcOffset, dstOffset, size};
                vkCmdCopyBuffer(pc.cmd(), pc.buffer(d.src), pc.buffer(d.dst), 1, &region);
            })
        .dst;
}

}  // namespace ppr::passes
