// glTF alphaMode MASK: a surface cut out everywhere leaves no trace (G-buffer, shadow map, PPR's
// reflection of it), and one that passes the cutoff everywhere renders exactly as opaque.
// Validation + synchronization validation on.
#include "gpu_test_util.hpp"


namespace ppr::test {
namespace {

constexpr VkExtent2D kSize{320, 180};

util::Rgba8Image render(scene::Scene s, const std::string& camera, const std::string& technique = "ppr", VkExtent2D size = kSize) {
    GpuFixture f(std::move(s));
    f.headless->setTechnique(technique);
    util::Rgba8Image image = f.headless->capture(f.camera(camera), size, 1).image;
    EXPECT_EQ(f.ctx->validationErrors(), 0u);
    return image;
}

// The red material (crates and a sphere, seen in the puddles, casting shadows) cut out everywhere, and
// the same draws taken away (bounds, and so the shadow map's frustum, kept).
struct CutOut {
    scene::Scene base, masked, removed;
    CutOut() : base(scene::loadGltf(PPR_DEFAULT_SCENE_FILE)) {
        const int red = materialNamed(base, "paint_red");
        masked = base;
        masked.materials[size_t(red)].masked = true;
        masked.materials[size_t(red)].alphaCutoff = 0.5f;
        masked.materials[size_t(red)].baseColorFactor.a = 0.2f;
        removed = base;
        std::erase_if(removed.draws, [&](const scene::DrawItem& d) { return removed.meshes[d.mesh].material == red; });
    }
};

TEST(AlphaMask, FullyCutOutSurfacesLeaveNoTrace) {
    const CutOut c;
    ASSERT_LT(c.removed.draws.size(), c.base.draws.size());
    for (const char* camera : {"overview", "puddles"}) {
        const util::Rgba8Image withRed = render(c.base, camera), cut = render(c.masked, camera), without = render(c.removed, camera);
        EXPECT_FALSE(identical(withRed, without)) << camera << ": the red objects should be visible";
        EXPECT_TRUE(identical(cut, without)) << camera << ": a fully cut-out surface left a trace";
    }
}

// The ray-traced reference's rays pass through them too (any-hit alpha test in its ray query).
TEST(AlphaMask, RayTracedReferenceSeesThroughCutOutSurfaces) {
    PPR_SKIP_WITHOUT_RAY_QUERY();
    const CutOut c;
    const VkExtent2D small{160, 90};
    const util::Rgba8Image without = render(c.removed, "puddles", "raytraced", small);
    EXPECT_FALSE(identical(render(c.base, "puddles", "raytraced", small), without));
    EXPECT_TRUE(identical(render(c.masked, "puddles", "raytraced", small), without));
}

TEST(AlphaMask, SurfacesAboveTheCutoffRenderAsOpaque) {
    const scene::Scene base = scene::loadGltf(PPR_DEFAULT_SCENE_FILE);
    scene::Scene masked = base;
    const int red = materialNamed(base, "paint_red");
    masked.materials[size_t(red)].masked = true;
    masked.materials[size_t(red)].alphaCutoff = 0.5f;  // base colour alpha 1 everywhere
    EXPECT_TRUE(identical(render(base, "overview"), render(masked, "overview")));
}

}  // namespace
}  // namespace ppr::test
