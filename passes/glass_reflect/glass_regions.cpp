#include "glass_reflect/glass_regions.hpp"

#include <algorithm>
#include <stdexcept>

namespace ppr::passes {

void GlassRegionTable::reserve(uint32_t reflectorCount) {
    reflectorCount = std::max(reflectorCount, 1u);
    if (reflectorCount > kMaxReflectors) throw std::logic_error("glass region table: too many reflectors");
    table_.assign(reflectorCount, gpu::GlassRegionData{});
    list_.assign(reflectorCount, 0u);
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
    for (const scene::GlassRegion& r : layout.regions) {
        if (r.reflectorIndex >= table_.size()) continue;
        table_[r.reflectorIndex] = pack(r);
        list_[n++] = r.reflectorIndex;
    }
}

GlassRegionBuffers GlassRegionTable::add(graph::RenderGraph& g) const {
    const VkDeviceSize tableBytes = table_.size() * sizeof(gpu::GlassRegionData), listBytes = list_.size() * sizeof(uint32_t);
    const graph::BufferHandle table = g.createBuffer("glass.regions", {tableBytes});
    const graph::BufferHandle list = g.createBuffer("glass.region_list", {listBytes});
    const GlassRegionBuffers& out = g.addPass<GlassRegionBuffers>(
        "ppr.glass.regions", graph::QueueKind::Transfer,
        [&](graph::PassBuilder& b, GlassRegionBuffers& d) {
            d.table = b.transferDst(table);
            d.list = b.transferDst(list);
        },
        [this, tableBytes, listBytes](const GlassRegionBuffers& d, graph::PassContext& pc) {
            vkCmdUpdateBuffer(pc.cmd(), pc.buffer(d.table), 0, tableBytes, table_.data());
            vkCmdUpdateBuffer(pc.cmd(), pc.buffer(d.list), 0, listBytes, list_.data());
        });
    return out;
}

}  // namespace ppr::passes
