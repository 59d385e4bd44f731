#include "glass_reflect/glass_regions.hpp"

#include <algorithm>
#include <cstring>

namespace ppr::passes {

GlassRegionBuffer::GlassRegionBuffer(const vk::Context& ctx, uint32_t framesInFlight) : ctx_(ctx), slots_(framesInFlight) { reserve(1); }

GlassRegionBuffer::~GlassRegionBuffer() {
    for (Slot& s : slots_) {
        vk::destroyBuffer(ctx_, s.table);
        vk::destroyBuffer(ctx_, s.list);
    }
}

void GlassRegionBuffer::reserve(uint32_t reflectorCount) {
    reflectorCount = std::max(reflectorCount, 1u);
    if (reflectorCount <= capacity_) return;
    vkDeviceWaitIdle(ctx_.device());  // frames in flight read the old buffers; a reflector change is rare
    for (uint32_t i = 0; i < slots_.size(); ++i) {
        Slot& s = slots_[i];
        vk::destroyBuffer(ctx_, s.table);
        vk::destroyBuffer(ctx_, s.list);
        const std::string suffix = "[" + std::to_string(i) + "]";
        s.table = vk::createBuffer(ctx_, reflectorCount * sizeof(gpu::GlassRegionData), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                   vk::MemoryUse::Upload, "glass regions" + suffix);
        s.list = vk::createBuffer(ctx_, reflectorCount * sizeof(uint32_t), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, vk::MemoryUse::Upload,
                                  "glass region list" + suffix);
    }
    capacity_ = reflectorCount;
}

gpu::GlassRegionData GlassRegionBuffer::pack(const scene::GlassRegion& r) {
    gpu::GlassRegionData d{};
    d.screenOrigin = glm::vec2(r.screen.x0, r.screen.y0);
    d.atlasOrigin = glm::vec2(r.atlasOrigin);
    d.atlasSize = glm::vec2(r.atlasSize);
    d.scale = r.scale;
    d.valid = 1u;
    return d;
}

void GlassRegionBuffer::write(uint32_t slot, const scene::GlassAtlasLayout& layout) {
    Slot& s = slots_[slot];
    auto* table = static_cast<gpu::GlassRegionData*>(s.table.mapped);
    auto* list = static_cast<uint32_t*>(s.list.mapped);
    std::memset(table, 0, capacity_ * sizeof(gpu::GlassRegionData));
    uint32_t n = 0;
    for (const scene::GlassRegion& r : layout.regions) {
        if (r.reflectorIndex >= capacity_) continue;
        table[r.reflectorIndex] = pack(r);
        list[n++] = r.reflectorIndex;
    }
    vmaFlushAllocation(ctx_.allocator(), s.table.allocation, 0, VK_WHOLE_SIZE);
    vmaFlushAllocation(ctx_.allocator(), s.list.allocation, 0, VK_WHOLE_SIZE);
}

}  // namespace ppr::passes
