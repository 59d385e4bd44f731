#pragma once
// Where the scene's one reflection probe sits (--set env_source=probe, docs/normalmaps.md), as pure
// math so it can be tested without a GPU.
#include "scene/reflector.hpp"
#include "scene/scene.hpp"

#include <vector>

namespace ppr::scene {

// Height of the probe above the main reflector plane: a standing viewer's eyes, where the cameras
// that look at floor reflections usually are.
constexpr float kProbeEyeHeight = 1.7f;

struct ProbePlacement {
    glm::vec3 centre{0.0f};
    glm::vec3 boxMin{0.0f}, boxMax{0.0f};  // the box lookups are parallax-corrected against: the scene's bounds
};

// The centre of the scene's bounds in x and z, kProbeEyeHeight above the main reflector plane (the
// upward-facing plane holding the most reflector area: the floor's puddles, a pool; the bounds' floor
// when no reflector faces up), kept inside the bounds.
ProbePlacement placeProbe(const Scene& scene, const std::vector<Reflector>& reflectors);

}  // namespace ppr::scene
