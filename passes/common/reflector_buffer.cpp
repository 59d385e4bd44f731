#include "common/reflector_buffer.hpp"

#include <algorithm>
#include <cstring>

namespace ppr::passes {

ReflectorBuffer::ReflectorBuffer(const vk::Context& ctx, uint32_t framesInFlight) : ctx_(ctx), slots_(framesInFlight) {}

ReflectorBuffer::~ReflectorBuffer() {
    for (Slot& s : slots_) {
        vk::destroyBuffer(ctx_, s.reflectors);
        vk::destroyBuffer(ctx_, s.order);
    }
}

std::vector<gpu::ReflectorData> ReflectorBuffer::pack(const std::vector<scene::Reflector>& rs, const scene::ReflectorGroups& groups) {
    std::vector<gpu::ReflectorData> out(rs.size());
    for (size_t i = 0; i < rs.size(); ++i) {
        const scene::Reflector& r = rs[i];
        gpu::ReflectorData& d = out[i];
        d.center = r.center;
        d.halfExtentU = r.halfExtents.x;
        d.normal = r.normal;
        d.halfExtentV = r.halfExtents.y;
        d.tangent = r.tangent;
        d.reflectance = r.reflectance;
        d.bitangent = r.bitangent();
        d.orientationGroup = groups.orientationGroup[i];
        d.planeGroup = groups.planeGroup[i];
        d.kind = r.kind == scene::ReflectorKind::Glass ? gpu::kReflectorGlass : gpu::kReflectorOpaque;
        d.pad0 = d.pad1 = 0;
    }
    return out;
}

void ReflectorBuffer::update(uint32_t slot, const std::vector<scene::Reflector>& rs, uint64_t version) {
    if (groupsVersion_ != version) {
        groups_ = scene::groupReflectors(rs);
        groupsVersion_ = version;
        count_ = static_cast<uint32_t>(rs.size());
    }
    Slot& s = slots_[slot];
    if (s.version == version) return;
    const uint32_t n = std::max<uint32_t>(count_, 1);  // zero-sized buffers are not allowed
    if (n > s.capacity) {
        vk::destroyBuffer(ctx_, s.reflectors);
        vk::destroyBuffer(ctx_, s.order);
        s.reflectors = vk::createBuffer(ctx_, n * sizeof(gpu::ReflectorData), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, vk::MemoryUse::Upload,
                                        "reflectors[" + std::to_string(slot) + "]");
        s.order = vk::createBuffer(ctx_, n * sizeof(uint32_t), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, vk::MemoryUse::Upload,
                                   "reflector order[" + std::to_string(slot) + "]");
        s.capacity = n;
    }
    const std::vector<gpu::ReflectorData> data = pack(rs, groups_);
    if (!data.empty()) {
        std::memcpy(s.reflectors.mapped, data.data(), data.size() * sizeof(gpu::ReflectorData));
        std::memcpy(s.order.mapped, groups_.projectionOrder.data(), groups_.projectionOrder.size() * sizeof(uint32_t));
    }
    vmaFlushAllocation(ctx_.allocator(), s.reflectors.allocation, 0, VK_WHOLE_SIZE);
    vmaFlushAllocation(ctx_.allocator(), s.order.allocation, 0, VK_WHOLE_SIZE);
    s.version = version;
}

}  // namespace ppr::passes
