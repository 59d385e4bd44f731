#pragma once
// Transfer work that needs nothing earlier in the frame (clears, empty dispatch lists, small uploads),
// queued by several passes and recorded as one graph pass: one barrier batch and one timing where a
// pass each cost about 0.1 ms on lavapipe (its barrier and timestamps; docs/performance.md, "One
// transfer pass for PPR's clears"). Queue, then add(): the cleared or written versions are stored
// where the queueing calls pointed, and are valid from then on.
// With FrameInputs::computeClear (a GPU) an image clear is ImageClear's compute pass of its own,
// named as the call says; buffers are always written by the transfer pass.
#include "common/frame_inputs.hpp"
#include "graph/graph.hpp"

#include <string>
#include <vector>

namespace ppr::passes {

class TransferBatch {
public:
    TransferBatch() = default;  // every clear a transfer clear
    explicit TransferBatch(const FrameInputs& in) : computeClear_(in.computeClear ? in.clear : nullptr) {}

    // `image` cleared to `value`; `computePassName` names its pass where clears run as compute.
    void clearImage(graph::ImageHandle image, const VkClearColorValue& value, std::string computePassName, graph::ImageHandle* cleared);
    // `bytes` of `data` (a multiple of 4, at most 65536: vkCmdUpdateBuffer) written at the buffer's
    // start and, with `zeroRest`, every byte after them zeroed. The data is read when the frame is
    // recorded: it must stay untouched until then.
    void writeBuffer(graph::BufferHandle buffer, const void* data, VkDeviceSize bytes, bool zeroRest, graph::BufferHandle* written);
    // The buffer's first TileDispatchArgs an empty list (x = 0, y = z = 1), the rest zeroed with `zeroRest`.
    void emptyDispatchList(graph::BufferHandle buffer, bool zeroRest, graph::BufferHandle* cleared);

    // Adds the transfer pass `passName` (none when only compute clears or nothing was queued) and the
    // compute clears; every queued handle is written.
    void add(graph::RenderGraph& g, const std::string& passName);

private:
    struct ImageItem {
        graph::ImageHandle image;
        VkClearColorValue value;
        std::string computePassName;
        graph::ImageHandle* cleared;
    };
    struct BufferItem {
        graph::BufferHandle buffer;
        const void* data;
        VkDeviceSize bytes;
        bool zeroRest;
        graph::BufferHandle* written;
    };
    const ImageClear* computeClear_ = nullptr;  // set: images are cleared by compute passes
    std::vector<ImageItem> images_;
    std::vector<BufferItem> buffers_;
};

}  // namespace ppr::passes
