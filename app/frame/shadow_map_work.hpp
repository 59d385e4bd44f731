#pragma once
// shadow_cache=1 (frame/shadow_map_cache.hpp): what a frame must draw of the kept shadow maps. Pure
// logic, unit-tested without a GPU.
#include <cstdint>
#include <optional>
#include <string>

namespace ppr::app {

// What the frame's map depends on besides the scene and the light, which a renderer never changes.
struct ShadowMapKey {
    uint32_t resolution = 0;
    std::optional<double> pose;  // an animated scene's clock; none: the pose as loaded
    bool operator==(const ShadowMapKey&) const = default;
};

// What a frame must draw given what the kept maps were drawn for.
struct ShadowMapWork {
    bool still = false;   // draw the still casters' map (first frame, new resolution)
    bool moving = false;  // copy it into the frame map and draw the moving casters over it
    bool operator==(const ShadowMapWork&) const = default;
};
constexpr ShadowMapWork shadowMapWork(const std::optional<ShadowMapKey>& drawn, const ShadowMapKey& now, bool animated) {
    const bool still = !drawn || drawn->resolution != now.resolution;
    return {still, animated && (still || drawn->pose != now.pose)};
}

// The viewer's line under its pass timings, where the shadow pass is missing from a frame that
// reads the kept map: how many frames drew each map (`kept`: shadow_cache=1).
inline std::string shadowMapSummary(bool kept, bool animated, uint64_t stillDraws, uint64_t movingDraws) {
    if (!kept) return "shadow map: drawn every frame (shadow_cache=0)";
    std::string s = "shadow map: kept; still casters drawn " + std::to_string(stillDraws) + (stillDraws == 1 ? " time" : " times");
    if (animated) s += ", moving ones " + std::to_string(movingDraws);
    return s;
}

}  // namespace ppr::app
