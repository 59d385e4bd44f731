// Headless capture of the default scene, in-process, with validation + synchronization validation.
#include "gpu_test_util.hpp"

namespace ppr::test {
namespace {

TEST(Capture, RendersNonBlankImagesWithoutValidationErrors) {
    GpuFixture f;
    for (VkExtent2D size : {VkExtent2D{320, 180}, VkExtent2D{640, 360}}) {
        app::CaptureResult r = f.headless->capture(f.camera("overview"), size, 2);
        ASSERT_EQ(r.image.width, size.width);
        ASSERT_EQ(r.image.height, size.height);
        EXPECT_GT(lumaStdDev(r.image), 10.0) << "image looks blank at " << size.width << "x" << size.height;
        // Every pass of the frame was timed.
        for (const char* pass : {"shadow", "gbuffer", "lighting", "composite", "tonemap"}) {
            ASSERT_TRUE(r.passMedianMs.count(pass)) << pass;
            EXPECT_GE(r.passMedianMs.at(pass), 0.0);
        }
        EXPECT_GT(r.totalMedianMs, 0.0);
        EXPECT_EQ(r.timedFrames, 2u) << "a frame was culled away or not timed";
    }
    EXPECT_EQ(f.ctx->validationErrors(), 0u);
}

TEST(Capture, SameViewTwiceIsIdenticalAndResizeWorks) {
    GpuFixture f;
    const scene::CameraPose cam = f.camera("puddles");
    app::CaptureResult a = f.headless->capture(cam, {320, 180}, 1);
    app::CaptureResult b = f.headless->capture(cam, {640, 360}, 1);  // resize between captures
    app::CaptureResult c = f.headless->capture(cam, {320, 180}, 1);
    EXPECT_EQ(b.image.width, 640u);
    EXPECT_GT(lumaStdDev(b.image), 10.0);
    ASSERT_EQ(a.image.pixels.size(), c.image.pixels.size());
    EXPECT_TRUE(a.image.pixels == c.image.pixels) << "two captures of the same view differ";
    EXPECT_EQ(f.ctx->validationErrors(), 0u);
}

TEST(Capture, NoAllocationOnceThePoolIsWarm) {
    GpuFixture f;
    const scene::CameraPose cam = f.camera("overview");
    f.headless->capture(cam, {320, 180}, 3);
    const uint64_t warm = f.renderer->executor().poolAllocations();
    f.headless->capture(cam, {320, 180}, 4);
    EXPECT_EQ(f.renderer->executor().poolAllocations(), warm) << "the graph allocated resources on a warm frame";
    EXPECT_EQ(f.ctx->validationErrors(), 0u);
}

TEST(Capture, DebugViewsChangeTheImage) {
    GpuFixture f;
    const scene::CameraPose cam = f.camera("overview");
    app::CaptureResult lit = f.headless->capture(cam, {320, 180}, 1);
    f.headless->settings().set("debug", "normals");
    app::CaptureResult normals = f.headless->capture(cam, {320, 180}, 1);
    f.headless->settings().set("debug", "reflectors");
    app::CaptureResult reflectors = f.headless->capture(cam, {320, 180}, 1);
    EXPECT_FALSE(lit.image.pixels == normals.image.pixels);
    EXPECT_FALSE(lit.image.pixels == reflectors.image.pixels) << "no reflector ids in the G-buffer?";
    EXPECT_EQ(f.ctx->validationErrors(), 0u);
}

}  // namespace
}  // namespace ppr::test
