// The G-buffer's depth pre-pass (depth_prepass=1, passes/gbuffer/gbuffer_pass.hpp) changes what is
// shaded, never what is seen: the images with and without it are the same bit for bit. TAA's jitter
// moves every silhouette through 16 sub-pixel phases, where a pre-pass whose depth sat in front of
// the shading pass's own would leave holes, and the planar reference draws mirrored views. Masked
// surfaces are left out of the pre-pass: a cut-out one must not hide what lies behind it.
// Validation + synchronization validation on.
#include "gpu_test_util.hpp"

namespace ppr::test {
namespace {

constexpr VkExtent2D kSize{320, 180};

app::CaptureResult render(GpuFixture& f, const std::string& camera, bool prepass, uint32_t frames) {
    f.headless->settings().set("depth_prepass", prepass ? "1" : "0");
    return f.headless->capture(f.camera(camera), kSize, frames);
}

TEST(DepthPrepass, SameImagesThroughTheJitterCycle) {
    GpuFixture f;
    f.headless->settings().set("taa", "1");
    for (const char* camera : {"overview", "stairs", "mirror"}) {
        const app::CaptureResult with = render(f, camera, true, 16), without = render(f, camera, false, 16);
        EXPECT_TRUE(with.passMedianMs.count("gbuffer.prepass")) << camera;
        EXPECT_FALSE(without.passMedianMs.count("gbuffer.prepass")) << camera;
        EXPECT_TRUE(identical(with.image, without.image)) << camera << ": the pre-pass changed the image";
    }
    EXPECT_EQ(f.ctx->validationErrors(), 0u);
}

TEST(DepthPrepass, SameImagesInThePlanarReferencesMirroredViews) {
    GpuFixture f;
    f.headless->setTechnique("planar");
    for (const char* camera : {"puddles", "mirror"}) {
        const app::CaptureResult with = render(f, camera, true, 1), without = render(f, camera, false, 1);
        EXPECT_TRUE(identical(with.image, without.image)) << camera << ": the pre-pass changed the planar reference";
    }
    EXPECT_EQ(f.ctx->validationErrors(), 0u);
}

// The red material cut out everywhere (alpha 0.2 under a 0.5 cutoff): in the pre-pass its depth would
// hide the floor and walls behind it, which the shading pass then could not draw.
TEST(DepthPrepass, CutOutSurfacesHideNothing) {
    scene::Scene s = scene::loadGltf(PPR_DEFAULT_SCENE_FILE);
    const int red = materialNamed(s, "paint_red");
    s.materials[size_t(red)].masked = true;
    s.materials[size_t(red)].alphaCutoff = 0.5f;
    s.materials[size_t(red)].baseColorFactor.a = 0.2f;
    GpuFixture f(std::move(s));
    for (const char* camera : {"overview", "puddles"}) {
        const app::CaptureResult with = render(f, camera, true, 1), without = render(f, camera, false, 1);
        EXPECT_TRUE(identical(with.image, without.image)) << camera << ": a cut-out surface hid something in the pre-pass";
    }
    EXPECT_EQ(f.ctx->validationErrors(), 0u);
}

}  // namespace
}  // namespace ppr::test
