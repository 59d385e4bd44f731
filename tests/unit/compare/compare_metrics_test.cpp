// Scoring of a technique's reflection image against the planar reference: the mask, PSNR in display
// space, coverage, the region variant, half-float readback and the error heat map.
#include "metrics/compare_metrics.hpp"

#include "common/reflection.h"
#include "tonemap/tonemap.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

using namespace ppr::app;
using ppr::gpu::displayFromRadiance;
using ppr::gpu::kReflectionFilled;
using ppr::gpu::kReflectionHit;
using ppr::gpu::kReflectionNone;
using ppr::gpu::kReflectionOffscreen;
using ppr::gpu::kReflectionSecondary;
using ppr::gpu::kReflectionOffscreen;

namespace {

constexpr float kExposure = 1.0f;

void setPixel(FloatImage& img, uint32_t x, uint32_t y, glm::vec3 rgb, float alpha) {
    float* p = &img.rgba[(size_t(y) * img.width + x) * 4];
    p[0] = rgb.r, p[1] = rgb.g, p[2] = rgb.b, p[3] = alpha;
}

FloatImage makeImage(uint32_t w, uint32_t h, glm::vec3 rgb, float alpha) {
    FloatImage img{w, h, std::vector<float>(size_t(w) * h * 4)};
    for (uint32_t y = 0; y < h; ++y)
        for (uint32_t x = 0; x < w; ++x) setPixel(img, x, y, rgb, alpha);
    return img;
}

// Radiance whose display value is `target` (per channel, grey), by bisection: displayFromRadiance is
// monotonic in radiance.
float radianceForDisplay(float target) {
    float lo = 0.0f, hi = 64.0f;
    for (int i = 0; i < 100; ++i) {
        const float mid = 0.5f * (lo + hi);
        (displayFromRadiance(glm::vec3(mid), kExposure).x < target ? lo : hi) = mid;
    }
    return 0.5f * (lo + hi);
}

// MSE of two constant images, computed independently of compare_metrics.cpp.
double expectedMse(glm::vec3 tech, glm::vec3 ref) {
    const glm::vec3 a = displayFromRadiance(tech, kExposure), b = displayFromRadiance(ref, kExposure);
    double s = 0;
    for (int c = 0; c < 3; ++c) s += (double(a[c]) - b[c]) * (double(a[c]) - b[c]);
    return s / 3.0;
}

const uint8_t* px(const ppr::util::Rgba8Image& img, uint32_t x, uint32_t y) {
    return &img.pixels[(size_t(y) * img.width + x) * 4];
}

}  // namespace

TEST(CompareMetrics, IdenticalImagesScoreTheCap) {
    FloatImage ref = makeImage(8, 6, {0.3f, 0.6f, 1.2f}, kReflectionHit);
    setPixel(ref, 1, 1, {5, 0, 0}, kReflectionOffscreen);
    const ReflectionScore s = scoreReflection(ref, ref, kExposure);
    EXPECT_EQ(s.psnrDb, kPsnrCapDb);
    EXPECT_EQ(s.coverage, 1.0);
    EXPECT_EQ(s.mse, 0.0);
    EXPECT_EQ(s.maskPixels, 8u * 6u - 1u);
    EXPECT_EQ(s.coveredPixels, s.maskPixels);
}

TEST(CompareMetrics, ConstantDisplayErrorOfATenthIsTwentyDb) {
    const float r = radianceForDisplay(0.4f), t = radianceForDisplay(0.5f);
    const FloatImage ref = makeImage(16, 8, glm::vec3(r), kReflectionHit);
    const FloatImage tech = makeImage(16, 8, glm::vec3(t), kReflectionHit);
    const ReflectionScore s = scoreReflection(tech, ref, kExposure);
    const double mse = expectedMse(glm::vec3(t), glm::vec3(r));
    EXPECT_NEAR(s.mse, mse, 1e-12);
    EXPECT_NEAR(s.psnrDb, 10.0 * std::log10(1.0 / mse), 1e-6);
    EXPECT_NEAR(s.psnrDb, 20.0, 1e-3);  // display values found by bisection: float precision
    EXPECT_EQ(s.coverage, 1.0);
}

TEST(CompareMetrics, ErrorIsMeasuredAfterExposure) {
    const glm::vec3 ref(0.2f, 0.3f, 0.4f), tech(0.25f, 0.3f, 0.5f);
    const ReflectionScore s =
        scoreReflection(makeImage(4, 4, tech, kReflectionHit), makeImage(4, 4, ref, kReflectionHit), 2.0f);
    const glm::vec3 a = displayFromRadiance(tech, 2.0f), b = displayFromRadiance(ref, 2.0f);
    double mse = 0;
    for (int c = 0; c < 3; ++c) mse += (double(a[c]) - b[c]) * (double(a[c]) - b[c]) / 3.0;
    EXPECT_NEAR(s.mse, mse, 1e-12);
    EXPECT_NEAR(s.psnrDb, 10.0 * std::log10(1.0 / mse), 1e-6);
}

TEST(CompareMetrics, PixelsOutsideTheMaskAreIgnored) {
    FloatImage ref = makeImage(4, 4, {0.5f, 0.5f, 0.5f}, kReflectionHit);
    FloatImage tech = ref;
    // Reference alpha 0 (not a reflector) and 0.5 (off screen): the technique may do anything there.
    setPixel(ref, 0, 0, {0, 0, 0}, kReflectionNone);
    setPixel(tech, 0, 0, {1000, 0, 1000}, kReflectionHit);
    setPixel(ref, 3, 3, {0.1f, 0.1f, 0.1f}, kReflectionOffscreen);
    setPixel(tech, 3, 3, {0, 0, 0}, kReflectionNone);
    setPixel(ref, 2, 1, {0.1f, 0.1f, 0.1f}, kReflectionOffscreen);
    setPixel(tech, 2, 1, {NAN, 7, 0}, kReflectionFilled);
    const ReflectionScore s = scoreReflection(tech, ref, kExposure);
    EXPECT_EQ(s.maskPixels, 13u);
    EXPECT_EQ(s.coveredPixels, 13u);
    EXPECT_EQ(s.coverage, 1.0);
    EXPECT_EQ(s.psnrDb, kPsnrCapDb);
}

TEST(CompareMetrics, CoverageCountsAnyTechniqueAlphaAboveZero) {
    const FloatImage ref = makeImage(4, 2, {0.5f, 0.5f, 0.5f}, kReflectionHit);
    FloatImage tech = ref;
    for (uint32_t x = 0; x < 4; ++x) setPixel(tech, x, 1, {0.5f, 0.5f, 0.5f}, kReflectionFilled);
    ReflectionScore s = scoreReflection(tech, ref, kExposure);
    EXPECT_EQ(s.coverage, 1.0);  // 1.0 and 0.75 both count
    EXPECT_EQ(s.psnrDb, kPsnrCapDb);

    // Half the mask missing (alpha 0, rgb 0): coverage 0.5, and the missing half is an error.
    for (uint32_t x = 0; x < 4; ++x) setPixel(tech, x, 1, {0, 0, 0}, kReflectionNone);
    s = scoreReflection(tech, ref, kExposure);
    EXPECT_EQ(s.maskPixels, 8u);
    EXPECT_EQ(s.coveredPixels, 4u);
    EXPECT_EQ(s.coverage, 0.5);
    EXPECT_NEAR(s.mse, expectedMse({0, 0, 0}, {0.5f, 0.5f, 0.5f}) / 2.0, 1e-12);
    EXPECT_LT(s.psnrDb, kPsnrCapDb);
}

TEST(CompareMetrics, EmptyMaskScoresTheCapWithFullCoverage) {
    const FloatImage ref = makeImage(3, 3, {1, 1, 1}, kReflectionOffscreen);
    const FloatImage tech = makeImage(3, 3, {0, 0, 0}, kReflectionNone);
    const ReflectionScore s = scoreReflection(tech, ref, kExposure);
    EXPECT_EQ(s.maskPixels, 0u);
    EXPECT_EQ(s.psnrDb, kPsnrCapDb);
    EXPECT_EQ(s.coverage, 1.0);
    EXPECT_EQ(s.mse, 0.0);
}

TEST(CompareMetrics, NanInTheTechniqueIsAnErrorNotANanScore) {
    const FloatImage ref = makeImage(2, 2, {0, 0, 0}, kReflectionHit);
    FloatImage tech = ref;
    setPixel(tech, 0, 0, {NAN, NAN, NAN}, kReflectionHit);
    const ReflectionScore s = scoreReflection(tech, ref, kExposure);
    EXPECT_TRUE(std::isfinite(s.psnrDb));
    EXPECT_NEAR(s.mse, 0.25, 1e-12);  // one pixel of four at full error
}

TEST(CompareMetrics, SizeMismatchThrows) {
    const FloatImage a = makeImage(4, 4, {0, 0, 0}, kReflectionHit);
    const FloatImage b = makeImage(4, 5, {0, 0, 0}, kReflectionHit);
    EXPECT_THROW(scoreReflection(a, b, kExposure), std::invalid_argument);
    EXPECT_THROW(errorHeatMap(a, b, kExposure, {}), std::invalid_argument);
    FloatImage broken = a;
    broken.rgba.pop_back();
    EXPECT_THROW(scoreReflection(broken, a, kExposure), std::invalid_argument);
    EXPECT_THROW(reflectionDisplayImage(broken, kExposure), std::invalid_argument);
    ppr::util::Rgba8Image context{3, 4, std::vector<uint8_t>(3 * 4 * 4, 0)};
    EXPECT_THROW(errorHeatMap(a, a, kExposure, context), std::invalid_argument);
}

TEST(CompareMetrics, RegionCountsOnlyItsPixels) {
    const FloatImage ref = makeImage(8, 8, {0.5f, 0.5f, 0.5f}, kReflectionHit);
    FloatImage tech = ref;
    // Everything outside the 3x2 rectangle at (2, 5) is wrong and uncovered.
    for (uint32_t y = 0; y < 8; ++y)
        for (uint32_t x = 0; x < 8; ++x)
            if (x < 2 || x >= 5 || y < 5 || y >= 7) setPixel(tech, x, y, {0, 0, 0}, kReflectionNone);
    const ReflectionScore inside = scoreReflection(tech, ref, kExposure, PixelRect{2, 5, 3, 2});
    EXPECT_EQ(inside.maskPixels, 6u);
    EXPECT_EQ(inside.coverage, 1.0);
    EXPECT_EQ(inside.psnrDb, kPsnrCapDb);

    const ReflectionScore whole = scoreReflection(tech, ref, kExposure);
    EXPECT_EQ(whole.maskPixels, 64u);
    EXPECT_EQ(whole.coveredPixels, 6u);

    EXPECT_THROW(scoreReflection(tech, ref, kExposure, PixelRect{6, 0, 3, 1}), std::invalid_argument);
    EXPECT_THROW(scoreReflection(tech, ref, kExposure, PixelRect{0, 8, 1, 1}), std::invalid_argument);
}

TEST(CompareMetrics, FloatImageFromHalfRoundTripsKnownValues) {
    // 2x1 image: (1, 0.5, 0.75, 0), (0.75, 1, 0, 0.5)
    const uint16_t half[] = {0x3C00, 0x3800, 0x3A00, 0x0000, 0x3A00, 0x3C00, 0x0000, 0x3800};
    const FloatImage img = floatImageFromHalf(half, 2, 1);
    EXPECT_EQ(img.width, 2u);
    EXPECT_EQ(img.height, 1u);
    const std::vector<float> expected = {1.0f, 0.5f, 0.75f, 0.0f, 0.75f, 1.0f, 0.0f, 0.5f};
    EXPECT_EQ(img.rgba, expected);
    // The alpha codes survive the 16-bit round trip exactly, so the mask test can use ==.
    EXPECT_EQ(img.rgba[2], kReflectionFilled);
    EXPECT_EQ(img.rgba[7], kReflectionOffscreen);
    EXPECT_THROW(floatImageFromHalf(nullptr, 1, 1), std::invalid_argument);
}

TEST(CompareMetrics, ReflectionDisplayImageIsBlackWithoutAReflection) {
    FloatImage refl = makeImage(2, 1, {0.5f, 0.5f, 0.5f}, kReflectionFilled);
    setPixel(refl, 1, 0, {0.5f, 0.5f, 0.5f}, kReflectionNone);
    const ppr::util::Rgba8Image img = reflectionDisplayImage(refl, kExposure);
    const uint8_t v = static_cast<uint8_t>(std::lround(displayFromRadiance(glm::vec3(0.5f), kExposure).x * 255.0f));
    EXPECT_EQ(px(img, 0, 0)[0], v);
    EXPECT_EQ(px(img, 0, 0)[3], 255);
    EXPECT_EQ(px(img, 1, 0)[0], 0);
    EXPECT_EQ(px(img, 1, 0)[3], 255);
}

TEST(CompareMetrics, HeatMap) {
    // Row 0: mask, no error. Row 1: mask, big error. Row 2: offscreen. Row 3: not a reflector.
    FloatImage ref = makeImage(3, 4, {0.5f, 0.5f, 0.5f}, kReflectionHit);
    FloatImage tech = ref;
    for (uint32_t x = 0; x < 3; ++x) {
        setPixel(tech, x, 1, {100, 100, 100}, kReflectionHit);
        setPixel(ref, x, 1, {0, 0, 0}, kReflectionHit);
        setPixel(ref, x, 2, {1, 1, 1}, kReflectionOffscreen);
        setPixel(ref, x, 3, {0, 0, 0}, kReflectionNone);
    }
    ppr::util::Rgba8Image context{3, 4, std::vector<uint8_t>(3 * 4 * 4, 255)};
    for (uint32_t i = 0; i < 12; ++i) context.pixels[i * 4] = 200, context.pixels[i * 4 + 1] = 100, context.pixels[i * 4 + 2] = 40;

    const ppr::util::Rgba8Image heat = errorHeatMap(tech, ref, kExposure, context);
    ASSERT_EQ(heat.width, 3u);
    ASSERT_EQ(heat.height, 4u);
    for (uint32_t x = 0; x < 3; ++x) {
        const uint8_t* zero = px(heat, x, 0);
        EXPECT_EQ(zero[0] + zero[1] + zero[2], 0);
        const uint8_t* big = px(heat, x, 1);  // e ≈ 1 ≥ full scale: white
        EXPECT_EQ(big[0], 255);
        EXPECT_EQ(big[1], 255);
        EXPECT_EQ(big[2], 255);
        const uint8_t* grey = px(heat, x, 2);
        EXPECT_EQ(grey[0], 64);
        EXPECT_EQ(grey[1], 64);
        EXPECT_EQ(grey[2], 64);
        const uint8_t* ctx = px(heat, x, 3);  // 25 % of the context
        EXPECT_EQ(ctx[0], 50);
        EXPECT_EQ(ctx[1], 25);
        EXPECT_EQ(ctx[2], 10);
        for (uint32_t y = 0; y < 4; ++y) EXPECT_EQ(px(heat, x, y)[3], 255);
    }

    // Without a context image the rest is black.
    const ppr::util::Rgba8Image bare = errorHeatMap(tech, ref, kExposure, {});
    EXPECT_EQ(px(bare, 0, 3)[0], 0);
}

TEST(CompareMetrics, HeatMapRampIsMonotonic) {
    // Errors from 0 to full scale along one row: brightness (sum of channels) never decreases, the
    // first third is pure red, and half scale is red + half green (the way to yellow).
    const uint32_t w = 64;
    const float base = radianceForDisplay(0.2f);
    FloatImage ref = makeImage(w, 1, glm::vec3(base), kReflectionHit);
    FloatImage tech = ref;
    for (uint32_t x = 0; x < w; ++x)
        setPixel(tech, x, 0, glm::vec3(radianceForDisplay(0.2f + kHeatMapFullScale * float(x) / (w - 1))),
                 kReflectionHit);
    const ppr::util::Rgba8Image heat = errorHeatMap(tech, ref, kExposure, {});
    int prev = -1;
    for (uint32_t x = 0; x < w; ++x) {
        const uint8_t* p = px(heat, x, 0);
        const int sum = p[0] + p[1] + p[2];
        EXPECT_GE(sum, prev) << "x = " << x;
        prev = sum;
    }
    EXPECT_EQ(px(heat, w - 1, 0)[2], 255);  // full scale: white
    const uint8_t* third = px(heat, 10, 0);  // e ≈ 0.16 of full scale: red only
    EXPECT_GT(third[0], 0);
    EXPECT_EQ(third[1], 0);
    EXPECT_EQ(third[2], 0);
}

TEST(CompareMetrics, AllReflectorPixelsAddsTheOffscreenOnesAndKeepsSecondBouncesOut) {
    // One pixel of each kind in the reference; the technique reflects only the on-screen one.
    FloatImage ref = makeImage(4, 1, {0.5f, 0.5f, 0.5f}, kReflectionNone);
    setPixel(ref, 0, 0, {0.5f, 0.5f, 0.5f}, kReflectionHit);
    setPixel(ref, 1, 0, {0.5f, 0.5f, 0.5f}, kReflectionOffscreen);
    setPixel(ref, 2, 0, {0.5f, 0.5f, 0.5f}, kReflectionSecondary);
    FloatImage tech = makeImage(4, 1, {0, 0, 0}, kReflectionNone);
    setPixel(tech, 0, 0, {0.5f, 0.5f, 0.5f}, kReflectionHit);

    const ReflectionScore screen = scoreReflection(tech, ref, kExposure);
    EXPECT_EQ(screen.maskPixels, 1u);
    EXPECT_EQ(screen.psnrDb, kPsnrCapDb);

    const FloatImage all = allReflectorPixels(ref);
    const ReflectionScore everything = scoreReflection(tech, all, kExposure);
    EXPECT_EQ(everything.maskPixels, 2u);  // the hit and the off-screen pixel, not the second bounce
    EXPECT_EQ(everything.coverage, 0.5);
    EXPECT_NEAR(everything.mse, expectedMse({0, 0, 0}, {0.5f, 0.5f, 0.5f}) / 2.0, 1e-12);
    EXPECT_EQ(all.rgba[3 * 4 + 3], kReflectionNone);
    EXPECT_EQ(all.rgba[0], ref.rgba[0]);  // colours untouched
}

TEST(CompareMetrics, ImagePsnrOfWholeDisplayImages) {
    ppr::util::Rgba8Image a, b;
    a.width = b.width = 4;
    a.height = b.height = 2;
    a.pixels.assign(4 * 2 * 4, 100);
    b.pixels = a.pixels;
    EXPECT_EQ(imagePsnrDb(a, b), kPsnrCapDb);
    // Every colour channel off by 25 (up or down); alpha differs too but is not compared.
    for (size_t i = 0; i < b.pixels.size(); ++i)
        b.pixels[i] = static_cast<uint8_t>(i % 4 == 3 ? 0 : i % 2 ? 100 + 25 : 100 - 25);
    EXPECT_NEAR(imagePsnrDb(a, b), 10.0 * std::log10(1.0 / std::pow(25.0 / 255.0, 2)), 1e-9);
    b.width = 8;
    EXPECT_THROW(imagePsnrDb(a, b), std::invalid_argument);
}
