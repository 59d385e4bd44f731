#pragma once
// Which reflector each surface belongs to, as the G-buffer (gbuffer.frag) and the glass pass see it:
// per draw the reflector id (index + 1, 0 = none), plus the "loose" reflectors that no mesh belongs
// to (a rectangle the editor just snapped onto the floor): the G-buffer tests those per pixel. One
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
    // loose reflectors (at most kMaxLooseReflectors are tested). `version` changes with the set.
    void set(const std::vector<int>& drawReflector, const std::vector<uint32_t>& loose, uint64_t version);
    // Makes `slot`'s copy current (a no-op when it already is).
    void update(uint32_t slot);
    VkBuffer drawReflectors(uint32_t slot) const { return slots_[slot].draws.buffer; }  // uint per draw
    VkBuffer loose(uint32_t slot) const { return slots_[slot].loose.buffer; }           // uint[kMaxLooseReflectors]
    uint32_t looseCount() const { return static_cast<uint32_t>(loose_.size()); }

private:
    struct Slot {
        vk::Buffer draws, loose;
        uint64_t version = ~0ull;
    };
    const vk::Context& ctx_;
    std::vector<Slot> slots_;
    std::vector<uint32_t> drawIds_, loose_;
    uint64_t version_ = 0;
};

}  // namespace ppr::passes
