// Where the reflection probe sits (engine/scene/probe_placement.hpp).
#include "scene/probe_placement.hpp"

#include <gtest/gtest.h>

using namespace ppr::scene;

namespace {
Reflector flat(glm::vec3 center, glm::vec3 normal, glm::vec2 halfExtents) {
    Reflector r;
    r.center = center;
    r.normal = normal;
    r.tangent = std::abs(normal.x) > 0.9f ? glm::vec3(0, 0, 1) : glm::vec3(1, 0, 0);
    r.halfExtents = halfExtents;
    return r;
}
Scene box(glm::vec3 lo, glm::vec3 hi) {
    Scene s;
    s.boundsMin = lo;
    s.boundsMax = hi;
    return s;
}
}  // namespace

TEST(ProbePlacement, EyeHeightAboveThePlaneWithTheMostUpwardReflectorArea) {
    const Scene s = box({-12, 0, -10}, {8, 5, 10});
    const std::vector<Reflector> rs = {
        flat({0, 0.003f, 0}, {0, 1, 0}, {2, 2}),      // 16 m²: the floor's puddles...
        flat({5, 0.004f, 3}, {0, 1, 0}, {1, 1}),      // ...+4 m² in the same plane (to the centimetre)
        flat({-6, 0.6f, -3}, {0, 1, 0}, {3, 1.5f}),   // 18 m² of stair tread, higher up
        flat({0, 1.5f, -9.9f}, {0, 0, 1}, {10, 10}),  // a large wall mirror does not count
    };
    const ProbePlacement p = placeProbe(s, rs);
    EXPECT_FLOAT_EQ(p.centre.x, -2.0f);
    EXPECT_FLOAT_EQ(p.centre.z, 0.0f);
    EXPECT_NEAR(p.centre.y, 0.0f + kProbeEyeHeight, 1e-5f);
    EXPECT_EQ(p.boxMin, s.boundsMin);
    EXPECT_EQ(p.boxMax, s.boundsMax);
}

TEST(ProbePlacement, WithoutUpwardReflectorsAboveTheBoundsFloorAndInsideThem) {
    EXPECT_NEAR(placeProbe(box({0, -3, 0}, {2, 4, 2}), {}).centre.y, -3.0f + kProbeEyeHeight, 1e-5f);
    // A flat scene: the centre stays in the box.
    EXPECT_FLOAT_EQ(placeProbe(box({0, 0, 0}, {2, 0.5f, 2}), {flat({1, 0, 1}, {0, 1, 0}, {1, 1})}).centre.y, 0.5f);
}
