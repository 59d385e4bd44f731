#pragma once
// This frame's glass atlas layout on the GPU: GlassRegionData per reflector (glass_forward.h) and the
// list of reflectors that got a region, one host-visible copy per frame in flight, rewritten each
// frame into buffers sized once per reflector change (no per-frame allocation on the GPU side).
#include "glass_forward/glass_forward.h"
#include "scene/glass_atlas.hpp"
#include "vk/context.hpp"

#include <vector>

namespace ppr::passes {

class GlassRegionBuffer {
public:
    GlassRegionBuffer(const vk::Context& ctx, uint32_t framesInFlight);
    ~GlassRegionBuffer();
    GlassRegionBuffer(const GlassRegionBuffer&) = delete;
    GlassRegionBuffer& operator=(const GlassRegionBuffer&) = delete;

    // Sizes every slot for `reflectorCount` reflectors (waits for the device only when growing).
    void reserve(uint32_t reflectorCount);
    // Writes `slot`'s copy: the layout's regions, every other reflector invalid.
    void write(uint32_t slot, const scene::GlassAtlasLayout& layout);
    VkBuffer table(uint32_t slot) const { return slots_[slot].table.buffer; }  // GlassRegionData[reflectors]
    VkBuffer list(uint32_t slot) const { return slots_[slot].list.buffer; }    // uint[regions]

    // The region of one panel as the shaders see it (pure; unit-tested through the forward mapping).
    static gpu::GlassRegionData pack(const scene::GlassRegion& region);

private:
    struct Slot {
        vk::Buffer table, list;
    };
    const vk::Context& ctx_;
    std::vector<Slot> slots_;
    uint32_t capacity_ = 0;
};

}  // namespace ppr::passes
