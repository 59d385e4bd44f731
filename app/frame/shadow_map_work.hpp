#pragma once
// shadow_cache=1 (frame/shadow_map_cache.hpp): what a frame must draw of the kept shadow maps. Pure
// logic, unit-tested without a GPU.
#include <cstdint>
#include <optional>

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

}  // namespace ppr::app
