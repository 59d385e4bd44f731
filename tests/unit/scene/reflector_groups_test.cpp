// Orientation and plane groups of reflectors (engine/scene/reflector_groups.hpp).
#include "scene/reflector_groups.hpp"

#include <gtest/gtest.h>

using namespace ppr::scene;

namespace {
Reflector make(const char* name, glm::vec3 center, glm::vec3 normal, glm::vec3 tangent) {
    Reflector r;
    r.name = name;
    r.center = center;
    r.normal = glm::normalize(normal);
    r.tangent = glm::normalize(tangent);
    return r;
}
}  // namespace

TEST(ReflectorGroups, StairsAndPuddlesShareAnOrientationButNotAPlane) {
    const std::vector<Reflector> rs = {
        make("mirror", {0, 1.5f, -10}, {0, 0, 1}, {1, 0, 0}),
        make("puddle_a", {1, 0.005f, 0}, {0, 1, 0}, {1, 0, 0}),
        make("step_0", {-5, 0.15f, -3}, {0, 1, 0}, {1, 0, 0}),
        make("puddle_b", {4, 0.0052f, 2}, {0, 1, 0}, {0.8f, 0, 0.6f}),  // coplanar with puddle_a (0.2 mm)
        make("step_1", {-5, 0.30f, -3.4f}, {0, 1, 0}, {1, 0, 0}),
        make("back", {0, 1.5f, -10}, {0, 0, -1}, {1, 0, 0}),  // same plane, facing the other way
    };
    const ReflectorGroups g = groupReflectors(rs);
    EXPECT_EQ(g.orientationGroupCount, 3u);
    EXPECT_EQ(g.orientationGroup[1], g.orientationGroup[2]);
    EXPECT_EQ(g.orientationGroup[1], g.orientationGroup[3]);
    EXPECT_EQ(g.orientationGroup[1], g.orientationGroup[4]);
    EXPECT_NE(g.orientationGroup[0], g.orientationGroup[5]);
    EXPECT_EQ(g.planeGroupCount, 5u);
    EXPECT_EQ(g.planeGroup[1], g.planeGroup[3]);
    EXPECT_NE(g.planeGroup[2], g.planeGroup[4]);
    EXPECT_NE(g.planeGroup[0], g.planeGroup[5]);
    // Projection order: grouped by orientation, original order kept inside a group.
    EXPECT_EQ(g.projectionOrder, (std::vector<uint32_t>{0, 1, 2, 3, 4, 5}));
}

TEST(ReflectorGroups, ProjectionOrderGathersEachOrientation) {
    const std::vector<Reflector> rs = {
        make("a", {0, 0, 0}, {0, 1, 0}, {1, 0, 0}), make("b", {0, 0, 0}, {1, 0, 0}, {0, 0, 1}),
        make("c", {0, 1, 0}, {0, 1, 0}, {1, 0, 0}), make("d", {2, 0, 0}, {1, 0, 0}, {0, 1, 0}),
        make("e", {0, 0, 0}, {0, 0, 1}, {1, 0, 0})};
    const ReflectorGroups g = groupReflectors(rs);
    EXPECT_EQ(g.projectionOrder, (std::vector<uint32_t>{0, 2, 1, 3, 4}));
    for (size_t i = 1; i < g.projectionOrder.size(); ++i)
        EXPECT_LE(g.orientationGroup[g.projectionOrder[i - 1]], g.orientationGroup[g.projectionOrder[i]]);
    EXPECT_TRUE(groupReflectors({}).projectionOrder.empty());
}
