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
    // Blocks over the region and a one-texel ring around it (glass_reflect.comp writes the ring).
    const auto blocks = [](uint32_t texels) { return (texels + 2u + gpu::kGlassReflectGroupSize - 1u) / gpu::kGlassReflectGroupSize; };
    for (const scene::GlassRegion& r : layout.regions) {
        if (r.reflectorIndex >= table_.size()) continue;
        table_[r.reflectorIndex] = pack(r);
        blockStarts_[n] = blockCount_;
        blockCount_ += blocks(r.atlasSize.x) * blocks(r.atlasSize.y);
        list_[n++] = r.reflectorIndex;
    }
    blockStarts_[n] = blockCount_;
}

void GlassRegionTable::queue(graph::RenderGraph& g, TransferBatch& batch, GlassRegionBuffers* uploaded) const {
    batch.writeBuffer(g.createBuffer("glass.regions", {table_.size() * sizeof(gpu::GlassRegionData)}), table_.data(),
                      table_.size() * sizeof(gpu::GlassRegionData), false, &uploaded->table);
    batch.writeBuffer(g.createBuffer("glass.region_list", {list_.size() * sizeof(uint32_t)}), list_.data(), list_.size() * sizeof(uint32_t),
                      false, &uploaded->list);
    batch.writeBuffer(g.createBuffer("glass.region_blocks", {blockStarts_.size() * sizeof(uint32_t)}), blockStarts_.data(),
                      blockStarts_.size() * sizeof(uint32_t), false, &uploaded->blockStarts);
}

GlassRegionBuffers GlassRegionTable::add(graph::RenderGraph& g) const {
    TransferBatch batch;
    GlassRegionBuffers uploaded;
    queue(g, batch, &uploaded);
    batch.add(g, "ppr.glass.regions");
    return uploaded;
}

}  // namespace ppr::passes
