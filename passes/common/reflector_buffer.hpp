#pragma once
// The reflectors on the GPU: one host-visible copy per frame in flight, rewritten only when the
// reflector set changes (a version number), never per frame. A slot's copy is rewritten just before
// that slot records, after its fence, so no frame in flight ever sees a half-written buffer.
#include "common/reflector_data.h"
#include "ppr_common/tile_culling.h"
#include "ppr_common/tiles.h"
#include "scene/reflector.hpp"
#include "scene/reflector_groups.hpp"
#include "vk/context.hpp"

#include <vector>

namespace ppr::passes {

class ReflectorBuffer {
public:
    ReflectorBuffer(const vk::Context& ctx, uint32_t framesInFlight);
    ~ReflectorBuffer();
    ReflectorBuffer(const ReflectorBuffer&) = delete;
    ReflectorBuffer& operator=(const ReflectorBuffer&) = delete;

    // Makes `slot`'s copy hold `reflectors` (a no-op when `version` is what the slot already holds).
    void update(uint32_t slot, const std::vector<scene::Reflector>& reflectors, uint64_t version);

    VkBuffer reflectors(uint32_t slot) const { return slots_[slot].reflectors.buffer; }  // ReflectorData[]
    VkBuffer order(uint32_t slot) const { return slots_[slot].order.buffer; }            // uint[projected()] projection order
    // The first reflector of each cull plane (ReflectorData::cullPlane indexes this), at most kPprMaxCullPlanes.
    VkBuffer planeLeaders(uint32_t slot) const { return slots_[slot].planeLeaders.buffer; }
    uint32_t cullPlaneCount() const { return static_cast<uint32_t>(planeLeaders_.size()); }
    uint32_t count() const { return count_; }
    // How many PPR projects: the first kPprMaxReflectors in scene order (the rest are ignored).
    uint32_t projected() const { return projected_; }
    const scene::ReflectorGroups& groups() const { return groups_; }

    // Per reflector, the first reflector lying in the same plane (itself if none; pure, unit-tested).
    // ReflectorData::cullPlane is the index of that one among cullPlaneLeaders().
    static std::vector<uint32_t> cullPlanes(const std::vector<scene::Reflector>& reflectors, const scene::ReflectorGroups& groups);
    // The reflectors that lead a cull plane, in scene order, the first kPprMaxCullPlanes of them.
    static std::vector<uint32_t> cullPlaneLeaders(const std::vector<uint32_t>& planes);
    static std::vector<gpu::ReflectorData> pack(const std::vector<scene::Reflector>& reflectors, const scene::ReflectorGroups& groups);

private:
    struct Slot {
        vk::Buffer reflectors, order, planeLeaders;
        uint64_t version = ~0ull;
        uint32_t capacity = 0;
    };
    const vk::Context& ctx_;
    std::vector<Slot> slots_;
    scene::ReflectorGroups groups_;
    uint64_t groupsVersion_ = ~0ull;
    uint32_t count_ = 0;
    uint32_t projected_ = 0;
    std::vector<uint32_t> projectionOrder_;
    std::vector<uint32_t> planeLeaders_;
};

}  // namespace ppr::passes
