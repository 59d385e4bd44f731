#pragma once
// The moving draws of an animated scene (scene::SceneAnimation) on the GPU. Per frame in flight, a
// host-visible copy of the draw records whose moving entries are rewritten each frame, and the
// per-object motion table TAA reads (gpu::MotionData). Host writes into a slot happen after that
// slot's fence, and a submit makes them visible: no barrier, no per-frame allocation.
#include "gpu/scene_data.h"
#include "scene/scene.hpp"
#include "vk/context.hpp"

#include <optional>
#include <vector>

namespace ppr::gpu {

class SceneMotion {
public:
    // `records`: every draw's record at rest (motionSlot already set for the moving ones).
    SceneMotion(const vk::Context& ctx, const scene::Scene& scene, const std::vector<DrawData>& records, uint32_t framesInFlight);
    ~SceneMotion();
    SceneMotion(const SceneMotion&) = delete;
    SceneMotion& operator=(const SceneMotion&) = delete;

    // Poses the moving draws for frame `slot`: at `seconds` on the animation's clock, or at rest
    // (nullopt: the loaded pose). `cut`: a new shot, so nothing moved since "last frame".
    void pose(uint32_t slot, std::optional<double> seconds, bool cut);
    VkBuffer draws(uint32_t slot) const { return slots_[slot].draws.buffer; }
    VkBuffer motion(uint32_t slot) const { return slots_[slot].motion.buffer; }
    // The moving draws' world matrices of the last pose(), in SceneAnimation::draws order.
    const std::vector<glm::mat4>& worlds() const { return worlds_; }
    // The motion slot of moving draw `i` (SceneAnimation::draws order): 1..kMaxMovingDraws, 0 beyond.
    static uint32_t slotOf(size_t i) { return i < kMaxMovingDraws ? static_cast<uint32_t>(i + 1) : 0u; }

private:
    struct Slot {
        vk::Buffer draws, motion;
    };
    const vk::Context& ctx_;
    const scene::Scene& scene_;
    std::vector<Slot> slots_;
    std::vector<glm::mat4> worlds_, previous_;
    bool havePrevious_ = false;
};

}  // namespace ppr::gpu
