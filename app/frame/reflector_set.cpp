#include "frame/reflector_set.hpp"

#include <algorithm>

namespace ppr::app {

ReflectorSet::ReflectorSet(const vk::Context& ctx, const scene::Scene& scene, uint32_t framesInFlight) : scene_(scene) {
    buffer_ = std::make_unique<passes::ReflectorBuffer>(ctx, framesInFlight);
    surfaces_ = std::make_unique<passes::SurfaceBindingBuffer>(ctx, framesInFlight, static_cast<uint32_t>(scene.draws.size()));
}

void ReflectorSet::set(std::vector<scene::Reflector> reflectors) {
    list_ = std::move(reflectors);
    ++version_;
    budgetWarning_.clear();
    if (list_.size() > gpu::kPprMaxReflectors) {
        const size_t extra = list_.size() - gpu::kPprMaxReflectors;
        budgetWarning_ = std::to_string(list_.size()) + " reflectors exceed PPR's budget of " + std::to_string(gpu::kPprMaxReflectors) +
                         ": the last " + std::to_string(extra) + " (from '" + list_[gpu::kPprMaxReflectors].name + "' on) get no PPR reflection";
    }
    // Surfaces follow the list by name (and geometry); reflectors no mesh belongs to are found per pixel.
    const std::vector<int> binding = scene::bindDraws(scene_, list_);
    std::vector<bool> bound(list_.size(), false);
    for (int r : binding)
        if (r >= 0) bound[size_t(r)] = true;
    const size_t projected = std::min<size_t>(list_.size(), gpu::kPprMaxReflectors);
    std::vector<uint32_t> loose, looseGlass;
    glassIndices_.clear();
    for (size_t i = 0; i < projected; ++i) {
        const bool glass = list_[i].kind == scene::ReflectorKind::Glass;
        if (!bound[i]) (glass ? looseGlass : loose).push_back(static_cast<uint32_t>(i));
        if (glass) glassIndices_.push_back(static_cast<uint32_t>(i));
    }
    surfaces_->set(binding, loose, looseGlass, version_);
}

void ReflectorSet::update(uint32_t slot) {
    buffer_->update(slot, list_, version_);
    surfaces_->update(slot);
}

}  // namespace ppr::app
