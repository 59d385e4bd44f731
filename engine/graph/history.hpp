#pragma once
// History resources: images and buffers whose contents live from one frame to the next (TAA, temporal
// denoisers). Each entry is a ping-pong pair: every frame a pass reads `previous` (what was written
// last frame) and writes `current`; HistoryStore::endFrame() swaps the pair.
//
// The pair is imported into each frame's RenderGraph (RenderGraph::history), so:
//  - its Vulkan state (layout, last stage/access) carries from frame to frame through the imports'
//    `state`, and the graph plans the cross-frame barriers like any other;
//  - it is never pooled or aliased with transients (the executor only pools non-imported resources);
//  - a pass writing `current` is never culled: a write to an import is observable outside the frame,
//    which is exactly what history is (compile.cpp's cull treats it as a side effect).
//
// Physical allocation is injected (HistoryAllocator), so the store and its tests never touch Vulkan;
// GraphExecutor::history() is a store backed by VMA (vkHistoryAllocator, history_vk.cpp).
#include "graph/graph.hpp"

#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace ppr::vk {
class Context;
}

namespace ppr::graph {

// create* return the physical objects (image + view / buffer); `desc` and `state` are set by the store.
struct HistoryAllocator {
    std::function<ExternalImage(const std::string& name, const ImageDesc& desc)> createImage;
    std::function<void(const ExternalImage& image)> destroyImage;
    std::function<ExternalBuffer(const std::string& name, const BufferDesc& desc)> createBuffer;
    std::function<void(const ExternalBuffer& buffer)> destroyBuffer;
};

// GPU allocator for GraphExecutor: VMA images/buffers with a fixed, broad usage (see history_vk.cpp).
HistoryAllocator vkHistoryAllocator(const vk::Context& ctx);

struct HistoryStatus {
    bool isImage = true;
    bool previousValid = false;  // what the next request this frame will report
    uint32_t resets = 0;         // resets with a reason (creation is not one)
    std::string lastResetReason;  // empty if never reset
    uint64_t lastResetFrame = 0;  // HistoryStore::frame() when it happened
};

class HistoryStore {
public:
    explicit HistoryStore(HistoryAllocator allocator);
    ~HistoryStore();  // frees every entry through the allocator
    HistoryStore(const HistoryStore&) = delete;
    HistoryStore& operator=(const HistoryStore&) = delete;

    // Ends the frame: every entry requested this frame swaps its pair; its `previous` is valid next
    // frame only if a kept pass wrote `current` (reported by RenderGraph::commitImportStates) and no
    // reset came after the request. Entries not requested this frame lose validity (their contents are
    // now older than one frame). GraphExecutor::execute calls this for its own store.
    void endFrame();

    // Marks the entry's `previous` as invalid (camera cut, technique change...). Throws for an unknown
    // name (a typo would otherwise silently keep ghosting history). Resources are kept.
    void reset(const std::string& name, const std::string& reason);
    void resetAll(const std::string& reason);

    // Frees the entries no frame has requested for more than `unusedFrames` frames (a mode switched
    // off: TAA's history must not stay at the size it last had). A later request creates the entry
    // anew, with no valid `previous`. Between frames only, with the device done with them.
    void trim(uint32_t unusedFrames);

    uint64_t frame() const { return frame_; }  // number of endFrame() calls so far
    size_t size() const { return entries_.size(); }
    bool contains(const std::string& name) const { return entries_.count(name) != 0; }
    std::optional<HistoryStatus> status(const std::string& name) const;
    // "history 'taa.color' reset: camera cut" lines, oldest first (the last kMaxLogLines are kept).
    const std::vector<std::string>& resetLog() const { return log_; }
    static constexpr size_t kMaxLogLines = 256;

    // The physical pair as of now (tests, debug views). Throws for an unknown name or the wrong kind.
    const ExternalImage& previousImage(const std::string& name) const;
    const ExternalImage& currentImage(const std::string& name) const;
    const ExternalBuffer& previousBuffer(const std::string& name) const;
    const ExternalBuffer& currentBuffer(const std::string& name) const;

private:
    friend class RenderGraph;

    struct Entry {
        bool isImage = true;
        ImageDesc imageDesc;
        BufferDesc bufferDesc;
        ExternalImage images[2];
        ExternalBuffer buffers[2];
        uint32_t current = 0;        // index of `current` in the pair
        bool previousValid = false;
        bool requested = false;      // this frame
        bool written = false;        // this frame, by a kept pass
        bool resetAfterRequest = false;  // this frame's `current` was built on history reset since
        uint64_t lastRequestedFrame = 0;  // frame() when last requested
        HistoryStatus status;
    };
    template <class External>
    struct Pair {
        External* previous = nullptr;
        External* current = nullptr;
        bool previousValid = false;
    };

    // Get-or-create for this frame; reallocates (and resets) when the descriptor changed.
    Pair<ExternalImage> requestImage(const std::string& name, const ImageDesc& desc);
    Pair<ExternalBuffer> requestBuffer(const std::string& name, const BufferDesc& desc);
    void markWritten(const std::string& name);

    Entry& begin(const std::string& name, bool isImage);
    const Entry& find(const std::string& name, bool isImage) const;
    void allocate(const std::string& name, Entry& e);
    void release(Entry& e);
    void resetEntry(const std::string& name, Entry& e, const std::string& reason);

    HistoryAllocator allocator_;
    std::map<std::string, Entry> entries_;  // node-based: the ExternalImage pointers graphs hold stay valid
    std::vector<std::string> log_;
    uint64_t frame_ = 0;
};

}  // namespace ppr::graph
