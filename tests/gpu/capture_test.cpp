// Headless capture of the default scene, in-process, with validation + synchronization validation.
#include "gpu_test_util.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace ppr::test {
namespace {

TEST(Capture, RendersNonBlankImagesWithoutValidationErrors) {
    GpuFixture f;
    for (VkExtent2D size : {VkExtent2D{320, 180}, VkExtent2D{640, 360}}) {
        app::CaptureResult r = f.headless->capture(f.camera("overview"), size, 2);
        ASSERT_EQ(r.image.width, size.width);
        ASSERT_EQ(r.image.height, size.height);
        EXPECT_GT(lumaStdDev(r.image), 10.0) << "image looks blank at " << size.width << "x" << size.height;
        // Every pass of the frame was timed; the kept shadow map (shadow_cache=1) is drawn in the first
        // frame only, and read by every later one.
        for (const char* pass : {"gbuffer", "lighting", "composite", "tonemap"}) {
            ASSERT_TRUE(r.passMedianMs.count(pass)) << pass;
            EXPECT_GE(r.passMedianMs.at(pass), 0.0);
        }
        EXPECT_EQ(r.passMedianMs.count("shadow"), size.width == 320 ? 1u : 0u);
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

// The viewer's render scale: the frame rendered at half the output's size and upscaled into it by
// the tonemap pass. The output is full size and is the half-size frame upscaled bilinearly; scale 1
// afterwards is the plain capture, bit for bit.
TEST(Capture, RenderScaleUpscalesAHalfSizeFrameIntoTheFullSizeImage) {
    GpuFixture f;
    const scene::CameraPose cam = f.camera("puddles");
    f.headless->setTechnique("ppr");
    const app::CaptureResult plain = f.headless->capture(cam, {320, 180}, 1);
    const app::CaptureResult half = f.headless->capture(cam, {160, 90}, 1);
    f.headless->setRenderScale(0.5f);
    const app::CaptureResult scaled = f.headless->capture(cam, {320, 180}, 1);
    EXPECT_THROW(f.headless->capture(cam, {320, 180}, 1, false, true), std::logic_error) << "the reflection readback needs scale 1";
    f.headless->setRenderScale(1.0f);
    const app::CaptureResult again = f.headless->capture(cam, {320, 180}, 1);
    ASSERT_EQ(scaled.image.width, 320u);
    ASSERT_EQ(scaled.image.height, 180u);
    EXPECT_GT(lumaStdDev(scaled.image), 10.0);
    // Against the half-size frame upscaled here the same way: output pixel centre (i + 0.5) / 320 lies
    // at half-size texel coordinate (i + 0.5) / 2 - 0.5 (clamped at the border), bilinear. The pass
    // blends radiance before the tone curve, this blends the displayed bytes: close, not equal.
    auto halfAt = [&](int x, int y, int c) {
        return double(half.image.pixels[(size_t(std::clamp(y, 0, 89)) * 160 + size_t(std::clamp(x, 0, 159))) * 4 + size_t(c)]);
    };
    double squared = 0.0;
    for (int y = 0; y < 180; ++y)
        for (int x = 0; x < 320; ++x) {
            const double u = (x + 0.5) / 2.0 - 0.5, v = (y + 0.5) / 2.0 - 0.5;
            const int x0 = int(std::floor(u)), y0 = int(std::floor(v));
            const double fx = u - x0, fy = v - y0;
            for (int c = 0; c < 3; ++c) {
                const double top = halfAt(x0, y0, c) * (1 - fx) + halfAt(x0 + 1, y0, c) * fx;
                const double bottom = halfAt(x0, y0 + 1, c) * (1 - fx) + halfAt(x0 + 1, y0 + 1, c) * fx;
                const double d = scaled.image.pixels[(size_t(y) * 320 + size_t(x)) * 4 + size_t(c)] - (top * (1 - fy) + bottom * fy);
                squared += d * d;
            }
        }
    const double psnr = 10.0 * std::log10(255.0 * 255.0 / (squared / (320.0 * 180.0 * 3.0)));
    // Measured 36.0 dB; the same comparison off by a quarter of a half-size texel gives 29.3, by a
    // half 25.7.
    EXPECT_GT(psnr, 33.0) << "the output is not the half-size frame upscaled bilinearly";
    // ... and not a plain full-size render either (it was rendered at half size).
    EXPECT_FALSE(scaled.image.pixels == plain.image.pixels);
    EXPECT_TRUE(again.image.pixels == plain.image.pixels) << "render scale 1 after 0.5 is not the plain capture";
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
