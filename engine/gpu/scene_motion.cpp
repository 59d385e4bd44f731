#include "gpu/scene_motion.hpp"

#include <glm/gtc/matrix_inverse.hpp>

#include <cmath>
#include <cstring>
#include <iostream>

namespace ppr::gpu {
namespace {

bool finite(const glm::mat4& m) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(m[c][r])) return false;
    return true;
}

}  // namespace

SceneMotion::SceneMotion(const vk::Context& ctx, const scene::Scene& scene, const std::vector<DrawData>& records, uint32_t framesInFlight)
    : ctx_(ctx), scene_(scene) {
    const VkDeviceSize drawBytes = std::max<VkDeviceSize>(records.size() * sizeof(DrawData), 16);
    const VkDeviceSize motionBytes = (kMaxMovingDraws + 1) * sizeof(MotionData);
    for (uint32_t s = 0; s < framesInFlight; ++s) {
        Slot slot;
        slot.draws = vk::createBuffer(ctx, drawBytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, vk::MemoryUse::Upload, "scene draws (moving)");
        std::memcpy(slot.draws.mapped, records.data(), records.size() * sizeof(DrawData));
        slot.motion = vk::createBuffer(ctx, motionBytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, vk::MemoryUse::Upload, "scene motion");
        auto* motion = static_cast<MotionData*>(slot.motion.mapped);
        for (uint32_t i = 0; i <= kMaxMovingDraws; ++i) motion[i].toPrevious = glm::mat4(1.0f);
        vmaFlushAllocation(ctx.allocator(), slot.draws.allocation, 0, VK_WHOLE_SIZE);
        vmaFlushAllocation(ctx.allocator(), slot.motion.allocation, 0, VK_WHOLE_SIZE);
        slots_.push_back(slot);
    }
    const size_t moving = scene.animation.draws.size();
    if (moving > kMaxMovingDraws)
        std::cerr << scene.sourcePath << ": " << moving << " moving draws; TAA follows the motion of the first " << kMaxMovingDraws
                  << ", the rest reproject with the camera alone\n";
    for (uint32_t d : scene.animation.draws)
        if (scene.draws[d].reflector >= 0) {
            // Reflector rectangles are still: a moving reflective surface leaves its reflector behind.
            std::cerr << scene.sourcePath << ": node '" << scene.draws[d].nodeName << "' moves but is bound to reflector "
                      << scene.reflectors[size_t(scene.draws[d].reflector)].name << ", which does not move with it\n";
            break;
        }
    worlds_.resize(moving);
    previous_.resize(moving);
    for (size_t i = 0; i < moving; ++i) worlds_[i] = scene.draws[scene.animation.draws[i]].world;
}

SceneMotion::~SceneMotion() {
    for (Slot& s : slots_) {
        vk::destroyBuffer(ctx_, s.draws);
        vk::destroyBuffer(ctx_, s.motion);
    }
}

void SceneMotion::pose(uint32_t slot, std::optional<double> seconds, bool cut) {
    const scene::SceneAnimation& animation = scene_.animation;
    previous_.swap(worlds_);
    if (seconds) {
        animation.evaluate(*seconds, worlds_);
        // Finite keys can still multiply to infinity (a hostile file): such a draw keeps its last pose
        // rather than feeding NaN to every pass.
        for (size_t i = 0; i < worlds_.size(); ++i)
            if (!finite(worlds_[i])) worlds_[i] = havePrevious_ ? previous_[i] : scene_.draws[animation.draws[i]].world;
    } else
        for (size_t i = 0; i < worlds_.size(); ++i) worlds_[i] = scene_.draws[animation.draws[i]].world;
    const bool still = cut || !havePrevious_;
    havePrevious_ = true;

    Slot& s = slots_[slot];
    auto* draws = static_cast<DrawData*>(s.draws.mapped);
    auto* motion = static_cast<MotionData*>(s.motion.mapped);
    for (size_t i = 0; i < worlds_.size(); ++i) {
        DrawData& d = draws[animation.draws[i]];
        d.world = worlds_[i];
        d.normalMatrix = glm::mat4(glm::inverseTranspose(glm::mat3(worlds_[i])));
        if (const uint32_t m = slotOf(i); m != 0)
            motion[m].toPrevious = still ? glm::mat4(1.0f) : previous_[i] * glm::inverse(worlds_[i]);
    }
    vmaFlushAllocation(ctx_.allocator(), s.draws.allocation, 0, VK_WHOLE_SIZE);
    vmaFlushAllocation(ctx_.allocator(), s.motion.allocation, 0, VK_WHOLE_SIZE);
}

}  // namespace ppr::gpu
