#include "common/surface_binding.hpp"

#include <algorithm>
#include <cstring>

namespace ppr::passes {

SurfaceBindingBuffer::SurfaceBindingBuffer(const vk::Context& ctx, uint32_t framesInFlight, uint32_t drawCount)
    : ctx_(ctx), slots_(framesInFlight), drawIds_(std::max(drawCount, 1u), 0u) {
    for (uint32_t i = 0; i < framesInFlight; ++i) {
        const std::string suffix = "[" + std::to_string(i) + "]";
        slots_[i].draws = vk::createBuffer(ctx, drawIds_.size() * sizeof(uint32_t), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, vk::MemoryUse::Upload,
                                           "draw reflectors" + suffix);
        slots_[i].loose = vk::createBuffer(ctx, gpu::kMaxLooseReflectors * sizeof(uint32_t), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                           vk::MemoryUse::Upload, "loose reflectors" + suffix);
        slots_[i].looseGlass = vk::createBuffer(ctx, gpu::kMaxLooseGlassReflectors * sizeof(uint32_t), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                                vk::MemoryUse::Upload, "loose glass reflectors" + suffix);
    }
}

SurfaceBindingBuffer::~SurfaceBindingBuffer() {
    for (Slot& s : slots_) {
        vk::destroyBuffer(ctx_, s.draws);
        vk::destroyBuffer(ctx_, s.loose);
        vk::destroyBuffer(ctx_, s.looseGlass);
    }
}

void SurfaceBindingBuffer::set(const std::vector<int>& drawReflector, const std::vector<uint32_t>& loose, const std::vector<uint32_t>& looseGlass,
                               uint64_t version) {
    for (size_t i = 0; i < drawReflector.size() && i < drawIds_.size(); ++i)
        drawIds_[i] = drawReflector[i] >= 0 ? static_cast<uint32_t>(drawReflector[i]) + 1u : 0u;
    loose_.assign(loose.begin(), loose.begin() + std::min<size_t>(loose.size(), gpu::kMaxLooseReflectors));
    looseGlass_.assign(looseGlass.begin(), looseGlass.begin() + std::min<size_t>(looseGlass.size(), gpu::kMaxLooseGlassReflectors));
    version_ = version;
}

void SurfaceBindingBuffer::update(uint32_t slot) {
    Slot& s = slots_[slot];
    if (s.version == version_) return;
    std::memcpy(s.draws.mapped, drawIds_.data(), drawIds_.size() * sizeof(uint32_t));
    if (!loose_.empty()) std::memcpy(s.loose.mapped, loose_.data(), loose_.size() * sizeof(uint32_t));
    if (!looseGlass_.empty()) std::memcpy(s.looseGlass.mapped, looseGlass_.data(), looseGlass_.size() * sizeof(uint32_t));
    vmaFlushAllocation(ctx_.allocator(), s.draws.allocation, 0, VK_WHOLE_SIZE);
    vmaFlushAllocation(ctx_.allocator(), s.loose.allocation, 0, VK_WHOLE_SIZE);
    vmaFlushAllocation(ctx_.allocator(), s.looseGlass.allocation, 0, VK_WHOLE_SIZE);
    s.version = version_;
}

}  // namespace ppr::passes
