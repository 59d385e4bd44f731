#include "common/transfer_batch.hpp"

#include "common/clear_pass.hpp"
#include "ppr_common/tiles.h"

#include <stdexcept>

namespace ppr::passes {

void TransferBatch::clearImage(graph::ImageHandle image, const VkClearColorValue& value, std::string computePassName,
                               graph::ImageHandle* cleared) {
    images_.push_back({image, value, std::move(computePassName), cleared});
}

void TransferBatch::writeBuffer(graph::BufferHandle buffer, const void* data, VkDeviceSize bytes, bool zeroRest,
                                graph::BufferHandle* written) {
    if (bytes % 4 != 0 || bytes > 65536 || (bytes > 0 && !data)) throw std::logic_error("transfer batch: vkCmdUpdateBuffer takes 4-byte multiples up to 65536");
    buffers_.push_back({buffer, data, bytes, zeroRest, written});
}

void TransferBatch::emptyDispatchList(graph::BufferHandle buffer, bool zeroRest, graph::BufferHandle* cleared) {
    static constexpr gpu::TileDispatchArgs kEmpty{0u, 1u, 1u};
    writeBuffer(buffer, &kEmpty, sizeof(kEmpty), zeroRest, cleared);
}

void TransferBatch::add(graph::RenderGraph& g, const std::string& passName) {
    const bool computeImages = computeClear_ != nullptr;
    if (computeImages)
        for (const ImageItem& item : images_) *item.cleared = computeClear_->addCompute(g, item.computePassName, item.image, item.value);
    if (buffers_.empty() && (computeImages || images_.empty())) return;

    struct Written {
        std::vector<graph::ImageHandle> images;
        std::vector<VkClearColorValue> values;  // per image
        std::vector<graph::BufferHandle> buffers;
        std::vector<BufferItem> writes;  // per buffer
    };
    const Written& written = g.addPass<Written>(
        passName, graph::QueueKind::Transfer,
        [&](graph::PassBuilder& b, Written& d) {
            if (!computeImages)
                for (const ImageItem& item : images_) {
                    d.images.push_back(b.transferDst(item.image));
                    d.values.push_back(item.value);
                }
            for (const BufferItem& item : buffers_) d.buffers.push_back(b.transferDst(item.buffer));
            d.writes = buffers_;
        },
        [](const Written& d, graph::PassContext& pc) {
            const VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
            for (size_t i = 0; i < d.images.size(); ++i)
                vkCmdClearColorImage(pc.cmd(), pc.image(d.images[i]), pc.layout(d.images[i]), &d.values[i], 1, &range);
            // The update and the fill of one buffer touch disjoint bytes: no barrier between them.
            for (size_t i = 0; i < d.buffers.size(); ++i) {
                const BufferItem& item = d.writes[i];
                const VkBuffer buffer = pc.buffer(d.buffers[i]);
                if (item.bytes > 0) vkCmdUpdateBuffer(pc.cmd(), buffer, 0, item.bytes, item.data);
                if (item.zeroRest && item.bytes < pc.size(d.buffers[i])) vkCmdFillBuffer(pc.cmd(), buffer, item.bytes, VK_WHOLE_SIZE, 0u);
            }
        });
    if (!computeImages)
        for (size_t i = 0; i < images_.size(); ++i) *images_[i].cleared = written.images[i];
    for (size_t i = 0; i < buffers_.size(); ++i) *buffers_[i].written = written.buffers[i];
}

}  // namespace ppr::passes
