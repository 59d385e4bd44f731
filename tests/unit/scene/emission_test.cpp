// Scene::opaqueMaterialEmits: whether the G-buffer needs its emissive target.
#include "scene/scene.hpp"

#include <gtest/gtest.h>

using namespace ppr::scene;

TEST(OpaqueEmission, OnlyAnOpaqueMaterialWithANonZeroFactorEmits) {
    Scene s;
    EXPECT_FALSE(s.opaqueMaterialEmits());  // no materials: the default one emits nothing
    s.materials.push_back(Material{.name = "plain"});
    s.materials.push_back(Material{.name = "dark texture", .emissiveTexture = 0});  // a texture under a zero factor
    s.materials.push_back(Material{.name = "glowing glass", .emissiveFactor = {1, 1, 1}, .transparent = true});
    EXPECT_FALSE(s.opaqueMaterialEmits());
    s.materials.push_back(Material{.name = "faint", .emissiveFactor = {0, 0, 1e-6f}});
    EXPECT_TRUE(s.opaqueMaterialEmits());
    s.materials.back().masked = true;  // a cut-out material is drawn into the G-buffer too
    EXPECT_TRUE(s.opaqueMaterialEmits());
}
