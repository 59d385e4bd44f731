#pragma once
// Turns a compiled RenderGraph into Vulkan commands: realizes transient resources from a pool keyed
// by descriptor (no allocation once the pool is warm), records the planned barriers (one
// vkCmdPipelineBarrier2 per pass), begins dynamic rendering for graphics passes, and wraps every pass
// in a debug label and a pair of GPU timestamps.
#include "graph/graph.hpp"
#include "graph/history.hpp"
#include "vk/context.hpp"

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace ppr::graph {

struct PassTiming {
    std::string name;
    double gpuMs = 0.0;
};

class GraphExecutor {
public:
    // framesInFlight: how many frames may be recorded before the oldest one's timings are read.
    GraphExecutor(const vk::Context& ctx, uint32_t framesInFlight, uint32_t maxPassesPerFrame = 64);
    ~GraphExecutor();
    GraphExecutor(const GraphExecutor&) = delete;
    GraphExecutor& operator=(const GraphExecutor&) = delete;

    // Records the compiled graph into cmd for frame slot `frameSlot` (< framesInFlight). The caller
    // submits cmd; imported resources' states are updated as if the commands had executed, and
    // history().endFrame() is called (one execute() per frame).
    void execute(RenderGraph& graph, VkCommandBuffer cmd, uint32_t frameSlot);

    // Resources that live from one frame to the next (TAA...), backed by VMA and destroyed with the
    // executor: `graph.history(executor.history(), "taa.color", desc)`. Never pooled with transients.
    HistoryStore& history() { return *history_; }
    const HistoryStore& history() const { return *history_; }

    // After the fence of the frame recorded in `frameSlot` has signalled: that frame's per-pass GPU
    // times, in execution order. Empty if nothing was recorded in that slot yet.
    std::vector<PassTiming> readTimings(uint32_t frameSlot);

    // Destroys pooled resources, and history entries, that have not been used for `unusedFrames`
    // executions (e.g. after a resize). Call only when the device is idle or the resources are no
    // longer in use.
    void trimPool(uint32_t unusedFrames);
    size_t pooledImageCount() const { return images_.size(); }
    size_t pooledBufferCount() const { return buffers_.size(); }
    uint64_t poolAllocations() const { return allocations_; }  // total ever created, for "no per-frame allocation" tests

private:
    // One pooled GPU object, reusable by any transient with the same descriptor and a subset of its usage.
    template <class Desc, class Usage, class Object>
    struct Pooled {
        Desc desc;
        Usage usage = 0;
        Object object;
        uint64_t lastUsedFrame = 0;
        bool inUse = false;
    };
    using PooledImage = Pooled<ImageDesc, VkImageUsageFlags, vk::Image>;
    using PooledBuffer = Pooled<BufferDesc, VkBufferUsageFlags, vk::Buffer>;
    template <class Entry, class Create>
    Entry& acquire(std::vector<Entry>& pool, const decltype(Entry::desc)& desc, decltype(Entry::usage) usage, Create&& create);
    struct TimingSlot {
        std::vector<std::string> passNames;
        uint32_t queryCount = 0;
    };

    const vk::Context& ctx_;
    std::unique_ptr<HistoryStore> history_;
    VkQueryPool queryPool_ = VK_NULL_HANDLE;
    uint32_t framesInFlight_;
    uint32_t maxPasses_;
    std::vector<TimingSlot> timingSlots_;
    std::vector<PooledImage> images_;
    std::vector<PooledBuffer> buffers_;
    uint64_t frameCounter_ = 0;
    uint64_t allocations_ = 0;
};

}  // namespace ppr::graph
