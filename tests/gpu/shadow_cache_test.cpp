// The kept shadow maps (shadow_cache=1, app/frame/shadow_map_cache.hpp) change what is drawn, never
// what is seen: the images with and without them are the same bit for bit, as the animated ball
// moves, pauses and the resolution changes, and the maps are drawn only when what casts them changed.
// Validation + synchronization validation on: the kept maps are written by one frame while the frame
// before, still in flight, reads them.
#include "gpu_test_util.hpp"
#include "scene/stress_scene.hpp"

namespace ppr::test {
namespace {

constexpr VkExtent2D kSize{320, 180};

app::CaptureResult render(GpuFixture& f, bool cache, std::optional<double> seconds, uint32_t frames = 3, const std::string& camera = "puddles") {
    f.headless->settings().set("shadow_cache", cache ? "1" : "0");
    f.headless->setSceneTime(seconds);
    return f.headless->capture(f.camera(camera), kSize, frames);
}

TEST(ShadowCache, SameImagesAsDrawingTheMapEveryFrame) {
    GpuFixture f;
    for (const char* technique : {"ppr", "planar"}) {
        f.headless->setTechnique(technique);
        // The ball at rest, raised, lower, and at rest again: each a new pose for the kept maps.
        for (std::optional<double> t : {std::optional<double>(), std::optional<double>(1.0), std::optional<double>(0.3), std::optional<double>()}) {
            const app::CaptureResult kept = render(f, true, t), drawn = render(f, false, t);
            EXPECT_TRUE(identical(kept.image, drawn.image)) << technique << " at " << (t ? std::to_string(*t) : "rest");
        }
    }
    f.headless->setTechnique("none");
    f.headless->settings().set("debug", "shadow");
    for (const char* res : {"1024", "2048"}) {
        f.headless->settings().set("shadowres", res);
        const app::CaptureResult kept = render(f, true, 1.0, 2, "overview"), drawn = render(f, false, 1.0, 2, "overview");
        EXPECT_TRUE(identical(kept.image, drawn.image)) << "debug=shadow, shadowres=" << res;
    }
    EXPECT_EQ(f.ctx->validationErrors(), 0u);
}

TEST(ShadowCache, DrawnOnlyWhenWhatCastsItChanges) {
    GpuFixture f;
    auto counts = [&]() { return f.renderer->shadowMapCache().counts(); };
    app::CaptureResult r = render(f, true, std::nullopt);
    EXPECT_EQ(counts().still, 1u);
    EXPECT_EQ(counts().moving, 1u);
    EXPECT_TRUE(r.passMedianMs.count("shadow") && r.passMedianMs.count("shadow.restore") && r.passMedianMs.count("shadow.moving"));
    r = render(f, true, std::nullopt, 3, "overview");  // another view, the same pose: nothing drawn
    EXPECT_EQ(counts().still, 1u);
    EXPECT_EQ(counts().moving, 1u);
    EXPECT_FALSE(r.passMedianMs.count("shadow") || r.passMedianMs.count("shadow.restore") || r.passMedianMs.count("shadow.moving"));
    render(f, true, 0.4);  // the ball moved: its shadow over the kept still map, once for three frames
    EXPECT_EQ(counts().still, 1u);
    EXPECT_EQ(counts().moving, 2u);
    f.headless->settings().set("shadowres", "1024");
    render(f, true, 0.4);
    EXPECT_EQ(counts().still, 2u);
    EXPECT_EQ(counts().moving, 3u);
    r = render(f, false, 0.4);  // every frame draws its own map; the kept ones are freed
    EXPECT_EQ(counts().still, 2u);
    EXPECT_TRUE(r.passMedianMs.count("shadow"));
    EXPECT_EQ(r.timedFrames, 3u);
    render(f, true, 0.4);  // and drawn again when the cache comes back
    EXPECT_EQ(counts().still, 3u);
    EXPECT_EQ(f.ctx->validationErrors(), 0u);
}

// A scene that does not move keeps one map: drawn once, read by every frame, no copy.
TEST(ShadowCache, AStillSceneDrawsItOnce) {
    GpuFixture f(scene::makeStressScene(16));
    f.headless->setTechnique("ppr");
    const app::CaptureResult kept = render(f, true, std::nullopt, 4, "overview");
    render(f, true, 2.0, 2, "reflective_25");  // a clock, but nothing it moves
    EXPECT_EQ(f.renderer->shadowMapCache().counts().still, 1u);
    EXPECT_EQ(f.renderer->shadowMapCache().counts().moving, 0u);
    EXPECT_FALSE(kept.passMedianMs.count("shadow.restore"));
    EXPECT_TRUE(identical(kept.image, render(f, false, std::nullopt, 4, "overview").image));
    EXPECT_EQ(f.ctx->validationErrors(), 0u);
}

}  // namespace
}  // namespace ppr::test
