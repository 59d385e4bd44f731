#pragma once
// shadow_cache=1: the sun's shadow map outlives the frame. The light is fixed, so only the casters the
// animation moves can change it: the still casters' map is drawn once (and again on a resolution
// change) and kept. A still scene reads it as it is. An animated scene's frame map is a second kept
// image: when the pose (the animation clock) changes, the still map is copied into it and the moving
// casters are drawn over it; a frame with the pose unchanged (a paused animation, the captures of
// named cameras) reads it as it is. On lavapipe the shadow pass was 7-9 ms of the default scene's
// frame at 1280x720 and 104 ms of the 1.1 M-triangle scale scene's (docs/performance.md). The maps
// are the same images the pass draws every frame with shadow_cache=0.
#include "frame/shadow_map_work.hpp"
#include "graph/graph.hpp"
#include "shadow/shadow_pass.hpp"
#include "vk/context.hpp"

#include <cstdint>

namespace ppr::app {

class ShadowMapCache {
public:
    ShadowMapCache(const vk::Context& ctx, const passes::ShadowPass& pass, bool animated) : ctx_(ctx), pass_(pass), animated_(animated) {}
    ~ShadowMapCache() { release(); }
    ShadowMapCache(const ShadowMapCache&) = delete;
    ShadowMapCache& operator=(const ShadowMapCache&) = delete;

    // This frame's shadow map, drawn first where `key` differs from what the kept maps hold. With
    // `enabled` false, a transient with every caster drawn this frame (the kept maps are freed).
    graph::ImageHandle add(graph::RenderGraph& g, const passes::FrameInputs& in, const ShadowMapKey& key, bool enabled);

    struct Counts {
        uint64_t still = 0;   // frames that drew the still casters' map
        uint64_t moving = 0;  // frames that drew the moving casters over it
    };
    Counts counts() const { return counts_; }
    bool animated() const { return animated_; }

private:
    void release();  // waits for the device: only on a resolution change, shadow_cache=0 and teardown

    const vk::Context& ctx_;
    const passes::ShadowPass& pass_;
    const bool animated_;  // the scene has moving casters: the frame map is a second image
    vk::Image still_, posed_;
    graph::ExternalImage stillImport_, posedImport_;
    std::optional<ShadowMapKey> drawn_;
    Counts counts_;
};

}  // namespace ppr::app
