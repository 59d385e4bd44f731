#pragma once
// This frame's glass atlas layout as graph buffers: GlassRegionData per reflector (glass_forward.h),
// the list of reflectors that got a region and where each listed region's blocks of the resolve
// start. The CPU packs the atlas; a transfer pass ("ppr.glass.regions", or PPR's "ppr.clear") writes all three with
// vkCmdUpdateBuffer, so the data travels inside the command buffer (no host-visible copies per frame
// in flight) and every reader declares it to the graph.
#include "common/transfer_batch.hpp"
#include "glass_forward/glass_forward.h"
#include "graph/graph.hpp"
#include "scene/glass_atlas.hpp"

#include <vector>

namespace ppr::passes {

struct GlassRegionBuffers {
    graph::BufferHandle table;  // GlassRegionData[reflectors]
    graph::BufferHandle list;   // uint[reflectors]: the first `regions` entries are the panes with a region
    // uint[reflectors + 1]: the first resolve workgroup of each listed region, then their total
    // (ppr.glass.reflect runs a kGlassReflectGroupSize² block per workgroup, regions one after another)
    graph::BufferHandle blockStarts;
};

class GlassRegionTable {
public:
    // vkCmdUpdateBuffer's limit: 65536 bytes, 2048 reflectors (PPR projects at most 1024).
    static constexpr uint32_t kMaxReflectors = 65536 / sizeof(gpu::GlassRegionData);

    // Sizes the CPU copies for `reflectorCount` reflectors (once per reflector change).
    void reserve(uint32_t reflectorCount);
    // This frame's layout: its regions, every other reflector invalid.
    void fill(const scene::GlassAtlasLayout& layout);
    // Adds the upload pass; the data must stay untouched until the frame is recorded.
    GlassRegionBuffers add(graph::RenderGraph& g) const;
    // The same upload queued in a technique's batch: `uploaded` after batch.add().
    void queue(graph::RenderGraph& g, TransferBatch& batch, GlassRegionBuffers* uploaded) const;

    // The region of one panel as the shaders see it.
    static gpu::GlassRegionData pack(const scene::GlassRegion& region);
    // The resolve's workgroups over this frame's regions (GlassRegionBuffers::blockStarts).
    uint32_t blockCount() const { return blockCount_; }
    const std::vector<uint32_t>& blockStarts() const { return blockStarts_; }  // as uploaded

private:
    std::vector<gpu::GlassRegionData> table_;
    std::vector<uint32_t> list_, blockStarts_;
    uint32_t blockCount_ = 0;
};

}  // namespace ppr::passes
