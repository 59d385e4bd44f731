#include "glass_reflect/glass_regions.hpp"

#include "glass_reflect/glass_reflect.h"

#include <algorithm>
#include <stdexcept>

namespace ppr::passes {

void GlassRegionTable::reserve(uint32_t reflectorCount) {
    reflectorCount = std::max(reflectorCount, 1u);
    if (reflectorCount > kMaxReflectors) throw std::logic_error("glass region table: too many reflectors");
    table_.assign(reflectorCount, gpu::GlassRegionData{});
    list_.assign(reflectorCount, 0u);
    blockStarts_.assign(reflectorCount + 1u, 0u);
}

gpu::GlassRegionData GlassRegionTable::pack(const scene::GlassRegion& r) {
    gpu::GlassRegionData d{};
    d.screenOrigin = glm::vec2(r.screen.x0, r.screen.y0);
    d.atlasOrigin = glm::vec2(r.atlasOrigin);
    d.atlasSize = glm::vec2(r.atlasSize);
    d.scale = r.scale;
    d.valid = 1u;
    return d;
}

void GlassRegionTable::fill(const scene::GlassAtlasLayout& layout) {
    std::fill(table_.begin(), table_.end(), gpu::GlassRegionData{});
    uint32_t n = 0;
    blockCount_ = 0;
    const auto blocks = [](uint32_t texels) { return (texels + gpu::kGlassReflectGroupSize - 1u) / gpu::kGlassReflectGroupSize; };
    for (const scene::GlassRegion& r : layout.regions) {
        if (r.reflectorIndex >= table_.size()) continue;
        table_[r.reflectorIndex] = pack(r);
        blockStarts_[n] = blockCount_;
        blockCount_ += blocks(r.atlasSize.x) * blocks(r.atlasSize.y);
        list_[n++] = r.reflectorIndex;
    }
    blockStarts_[n] = blockCount_;
}

GlassRegionBuffers GlassRegionTable::add(graph::RenderGraph& g) const {
    const VkDeviceSize tableBytes = table_.size() * sizeof(gpu::GlassRegionData), listBytes = list_.size() * sizeof(uint32_t);
    const graph::BufferHandle table = g.createBuffer("glass.regions", {tableBytes});
    const graph::BufferHandle list = g.createBuffer("glass.region_list", {listBytes});
    const VkDeviceSize startBytes = blockStarts_.size() * sizeof(uint32_t);
    const graph::BufferHandle starts = g.createBuffer("glass.region_blocks", {startBytes});
    const GlassRegionBuffers& out = g.addPass<GlassRegionBuffers>(
        "ppr.glass.regions", graph::QueueKind::Transfer,
        [&](graph::PassBuilder& b, GlassRegionBuffers& d) {
            d.table = b.transferDst(table);
            d.list = b.transferDst(list);
            d.blockStarts = b.transferDst(starts);
        },
        [this, tableBytes, listBytes, startBytes](const GlassRegionBuffers& d, graph::PassContext& pc) {
            vkCmdUpdateBuffer(pc.cmd(), pc.buffer(d.table), 0, tableBytes, table_.data());
            vkCmdUpdateBuffer(pc.cmd(), pc.buffer(d.list), 0, listBytes, list_.data());
            vkCmdUpdateBuffer(pc.cmd(), pc.buffer(d.blockStarts), 0, startBytes, blockStarts_.data());
        });
    return out;
}

}  // namespace ppr::passes
