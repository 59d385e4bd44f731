#include "scene/probe_placement.hpp"

#include <cmath>
#include <map>

namespace ppr::scene {

ProbePlacement placeProbe(const Scene& scene, const std::vector<Reflector>& reflectors) {
    ProbePlacement p;
    p.boxMin = scene.boundsMin;
    p.boxMax = scene.boundsMax;
    // Upward-facing reflector area per plane height, to the centimetre (stair treads are apart, a
    // puddle lifted 3 mm above the floor is not).
    std::map<long, float> areaAtHeight;
    for (const Reflector& r : reflectors)
        if (r.normal.y > 0.9f) areaAtHeight[std::lround(r.center.y * 100.0f)] += 4.0f * r.halfExtents.x * r.halfExtents.y;
    float floorY = scene.boundsMin.y, best = 0.0f;
    for (const auto& [cm, area] : areaAtHeight)
        if (area > best) best = area, floorY = static_cast<float>(cm) / 100.0f;
    p.centre = glm::vec3(0.5f * (p.boxMin.x + p.boxMax.x), floorY + kProbeEyeHeight, 0.5f * (p.boxMin.z + p.boxMax.z));
    p.centre = glm::clamp(p.centre, p.boxMin, p.boxMax);
    return p;
}

}  // namespace ppr::scene
