#include "common/reflector_buffer.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace ppr::passes {

ReflectorBuffer::ReflectorBuffer(const vk::Context& ctx, uint32_t framesInFlight) : ctx_(ctx), slots_(framesInFlight) {}

ReflectorBuffer::~ReflectorBuffer() {
    for (Slot& s : slots_) {
        vk::destroyBuffer(ctx_, s.reflectors);
        vk::destroyBuffer(ctx_, s.order);
        vk::destroyBuffer(ctx_, s.planeLeaders);
    }
}

std::vector<uint32_t> ReflectorBuffer::cullPlanes(const std::vector<scene::Reflector>& rs, const scene::ReflectorGroups& groups) {
    // Same plane to within what the culling slack absorbs: identical normal, offsets 10 µm apart.
    // Leaders are searched per orientation group (plane groups are not transitive).
    constexpr float kSamePlane = gpu::kPprCullPlaneTolerance;
    std::vector<uint32_t> out(rs.size());
    std::vector<std::vector<uint32_t>> leaders(groups.orientationGroupCount);
    for (uint32_t i = 0; i < rs.size(); ++i) {
        out[i] = i;
        for (uint32_t j : leaders[groups.orientationGroup[i]]) {
            if (rs[j].normal == rs[i].normal && std::abs(glm::dot(rs[i].center - rs[j].center, rs[j].normal)) <= kSamePlane) {
                out[i] = j;
                break;
            }
        }
        if (out[i] == i) leaders[groups.orientationGroup[i]].push_back(i);
    }
    return out;
}

std::vector<uint32_t> ReflectorBuffer::cullPlaneLeaders(const std::vector<uint32_t>& planes) {
    std::vector<uint32_t> leaders;
    for (uint32_t i = 0; i < planes.size() && leaders.size() < gpu::kPprMaxCullPlanes; ++i)
        if (planes[i] == i) leaders.push_back(i);
    return leaders;
}

std::vector<gpu::ReflectorData> ReflectorBuffer::pack(const std::vector<scene::Reflector>& rs, const scene::ReflectorGroups& groups) {
    std::vector<gpu::ReflectorData> out(rs.size());
    const std::vector<uint32_t> planes = cullPlanes(rs, groups);
    const std::vector<uint32_t> leaders = cullPlaneLeaders(planes);
    std::vector<uint32_t> compact(rs.size(), gpu::kPprNoCullPlane);  // leader reflector → its index in `leaders`
    for (uint32_t k = 0; k < leaders.size(); ++k) compact[leaders[k]] = k;
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
        d.cullPlane = compact[planes[i]];
        d.pad1 = 0;
    }
    return out;
}

void ReflectorBuffer::update(uint32_t slot, const std::vector<scene::Reflector>& rs, uint64_t version) {
    if (groupsVersion_ != version) {
        groups_ = scene::groupReflectors(rs);
        groupsVersion_ = version;
        count_ = static_cast<uint32_t>(rs.size());
        projected_ = std::min(count_, gpu::kPprMaxReflectors);
        // PPR's projection order keeps the first kPprMaxReflectors in scene order, still sorted by orientation.
        projectionOrder_.clear();
        for (uint32_t i : groups_.projectionOrder)
            if (i < projected_) projectionOrder_.push_back(i);
        planeLeaders_ = cullPlaneLeaders(cullPlanes(rs, groups_));
        planeLeaders_.erase(std::remove_if(planeLeaders_.begin(), planeLeaders_.end(), [&](uint32_t i) { return i >= projected_; }),
                            planeLeaders_.end());
    }
    Slot& s = slots_[slot];
    if (s.version == version) return;
    const uint32_t n = std::max<uint32_t>(count_, 1);  // zero-sized buffers are not allowed
    if (n > s.capacity) {
        vk::destroyBuffer(ctx_, s.reflectors);
        vk::destroyBuffer(ctx_, s.order);
        vk::destroyBuffer(ctx_, s.planeLeaders);
        s.planeLeaders = vk::createBuffer(ctx_, gpu::kPprMaxCullPlanes * sizeof(uint32_t), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                          vk::MemoryUse::Upload, "reflector cull planes[" + std::to_string(slot) + "]");
        s.reflectors = vk::createBuffer(ctx_, n * sizeof(gpu::ReflectorData), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, vk::MemoryUse::Upload,
                                        "reflectors[" + std::to_string(slot) + "]");
        s.order = vk::createBuffer(ctx_, n * sizeof(uint32_t), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, vk::MemoryUse::Upload,
                                   "reflector order[" + std::to_string(slot) + "]");
        s.capacity = n;
    }
    const std::vector<gpu::ReflectorData> data = pack(rs, groups_);
    if (!data.empty()) {
        std::memcpy(s.reflectors.mapped, data.data(), data.size() * sizeof(gpu::ReflectorData));
        std::memcpy(s.order.mapped, projectionOrder_.data(), projectionOrder_.size() * sizeof(uint32_t));
        std::memcpy(s.planeLeaders.mapped, planeLeaders_.data(), planeLeaders_.size() * sizeof(uint32_t));
    }
    vmaFlushAllocation(ctx_.allocator(), s.planeLeaders.allocation, 0, VK_WHOLE_SIZE);
    vmaFlushAllocation(ctx_.allocator(), s.reflectors.allocation, 0, VK_WHOLE_SIZE);
    vmaFlushAllocation(ctx_.allocator(), s.order.allocation, 0, VK_WHOLE_SIZE);
    s.version = version;
}

}  // namespace ppr::passes
