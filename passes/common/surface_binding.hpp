#pragma once
// Which reflector each surface belongs to, as the G-buffer (gbuffer.frag) and the glass pass see it:
// per draw the reflector id (index + 1, 0 = none), plus the "loose" reflectors that no mesh belongs
// to (a rectangle the editor just snapped onto the floor): the G-buffer tests those per pixel, and the
// glass forward pass the glass ones no glass draw belongs to (a draw holding many panes). One
// host-visible copy per frame in flight, rewritten only when the reflector set changes.
#include "gbuffer/gbuffer.h"
#include "vk/context.hpp"

#include <vector>

namespace ppr::passes {

class SurfaceBindingBuffer {
public:
    SurfaceBindingBuffer(const vk::Context& ctx, uint32_t framesInFlight, uint32_t drawCount);
    ~SurfaceBindingBuffer();
    SurfaceBindingBuffer(const SurfaceBindingBuffer&) = delete;
    SurfaceBindingBuffer& operator=(const SurfaceBindingBuffer&) = delete;

    // The binding for the next frames: per draw a reflector index or -1 (scene::bindDraws), and the
    // loose opaque and glass reflectors (at most kMaxLooseReflectors and kMaxLooseGlassReflectors are
    // tested). `version` changes with the set.
    void set(const std::vector<int>& drawReflector, const std::vector<uint32_t>& loose, const std::vector<uint32_t>& looseGlass,
             uint64_t version);
    // Makes `slot`'s copy current (a no-op when it already is).
    void update(uint32_t slot);
    VkBuffer drawReflectors(uint32_t slot) const { return slots_[slot].draws.buffer; }  // uint per draw
    VkBuffer loose(uint32_t slot) const { return slots_[slot].loose.buffer; }           // uint[kMaxLooseReflectors]
    uint32_t looseCount() const { return static_cast<uint32_t>(loose_.size()); }
    VkBuffer looseGlass(uint32_t slot) const { return slots_[slot].looseGlass.buffer; }  // uint[kMaxLooseGlassReflectors]
    uint32_t looseGlassCount() const { return static_cast<uint32_t>(looseGlass_.size()); }

private:
    struct Slot {
        vk::Buffer draws, loose, looseGlass;
        uint64_t version = ~0ull;
    };
    const vk::Context& ctx_;
    std::vector<Slot> slots_;
    std::vector<uint32_t> drawIds_, loose_, looseGlass_;
    uint64_t version_ = 0;
};

}  // namespace ppr::passes
