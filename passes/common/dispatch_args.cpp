#include "common/dispatch_args.hpp"

#include "ppr_common/tiles.h"

namespace ppr::passes {

graph::BufferHandle addEmptyDispatchList(graph::RenderGraph& g, const std::string& passName, graph::BufferHandle buffer, bool zeroRest) {
    struct Clear {
        graph::BufferHandle buffer;
    };
    return g
        .addPass<Clear>(
            passName, graph::QueueKind::Transfer, [&](graph::PassBuilder& b, Clear& d) { d.buffer = b.transferDst(buffer); },
            [zeroRest](const Clear& d, graph::PassContext& pc) {
                const gpu::TileDispatchArgs empty{0u, 1u, 1u};
                vkCmdUpdateBuffer(pc.cmd(), pc.buffer(d.buffer), 0, sizeof(empty), &empty);
                if (zeroRest) vkCmdFillBuffer(pc.cmd(), pc.buffer(d.buffer), sizeof(empty), VK_WHOLE_SIZE, 0u);
            })
        .buffer;
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
