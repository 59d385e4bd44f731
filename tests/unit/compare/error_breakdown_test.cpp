// compare's error breakdown: the worst-pixel shares, and each scored pixel's class from the
// reference's alpha codes, the planar reflected paths and the technique's hole-filled alpha.
#include "metrics/error_breakdown.hpp"

#include "common/reflection.h"
#include "planar/planar.h"

#include <gtest/gtest.h>

#include <stdexcept>

using namespace ppr::app;
using ppr::util::Rgba8Image;

namespace {

constexpr uint32_t kW = 9, kH = 7;

FloatImage reflection(float alpha) {
    FloatImage f{kW, kH, {}};
    f.rgba.assign(size_t(kW) * kH * 4, 0.0f);
    for (size_t i = 0; i < size_t(kW) * kH; ++i) f.rgba[i * 4 + 3] = alpha;
    return f;
}
void setAlpha(FloatImage& f, uint32_t x, uint32_t y, float a) { f.rgba[(size_t(y) * kW + x) * 4 + 3] = a; }

Rgba8Image grey(uint8_t v) {
    Rgba8Image img{kW, kH, {}};
    img.pixels.assign(size_t(kW) * kH * 4, v);
    return img;
}
void setGrey(Rgba8Image& img, uint32_t x, uint32_t y, uint8_t v) {
    for (int c = 0; c < 3; ++c) img.pixels[(size_t(y) * kW + x) * 4 + c] = v;
}

std::vector<float> paths(float length) {
    std::vector<float> p(size_t(kW) * kH * 2, 0.0f);
    for (size_t i = 0; i < size_t(kW) * kH; ++i) p[i * 2] = length;
    return p;
}

size_t at(uint32_t x, uint32_t y) { return size_t(y) * kW + x; }

}  // namespace

TEST(ErrorBreakdown, ClassesFollowTheReferenceInPrecedenceOrder) {
    FloatImage ref = reflection(ppr::gpu::kReflectionHit), tech = reflection(ppr::gpu::kReflectionHit);
    setAlpha(ref, 0, 3, ppr::gpu::kReflectionNone);       // not a reflector pixel: (1, y) are reflector edges
    setAlpha(ref, 5, 0, ppr::gpu::kReflectionOffscreen);  // a hidden reflected point: its neighbours are disocclusion edges
    std::vector<float> p = paths(10.0f);
    for (uint32_t y = 0; y < kH; ++y) p[at(7, y) * 2] = 20.0f;  // a far surface behind column 7: seams at 6 and 7
    p[at(3, 4) * 2 + 1] = ppr::gpu::pathTag(7u, ppr::gpu::kPlanarParallelShape);  // of a moving object
    p[at(3, 2) * 2 + 1] = ppr::gpu::pathTag(7u, 0u);  // a moving object's point alone is no class
    setAlpha(tech, 3, 5, ppr::gpu::kReflectionFilled);

    EXPECT_EQ(classifyPixel(tech, ref, p, at(0, 0)), ErrorClass::ReflectorEdge);  // the image border
    EXPECT_EQ(classifyPixel(tech, ref, p, at(1, 3)), ErrorClass::ReflectorEdge);
    EXPECT_EQ(classifyPixel(tech, ref, p, at(4, 1)), ErrorClass::DisocclusionEdge);
    EXPECT_EQ(classifyPixel(tech, ref, p, at(6, 3)), ErrorClass::SilhouetteSeam);
    EXPECT_EQ(classifyPixel(tech, ref, p, at(7, 3)), ErrorClass::SilhouetteSeam);
    EXPECT_EQ(classifyPixel(tech, ref, p, at(3, 4)), ErrorClass::ParallelShape);
    EXPECT_EQ(classifyPixel(tech, ref, p, at(3, 5)), ErrorClass::HoleFilled);
    EXPECT_EQ(classifyPixel(tech, ref, p, at(3, 2)), ErrorClass::Interior);
    // Without paths (a reference other than planar) nothing is a seam or a parallel shape.
    EXPECT_EQ(classifyPixel(tech, ref, {}, at(6, 3)), ErrorClass::Interior);
    EXPECT_EQ(classifyPixel(tech, ref, {}, at(3, 4)), ErrorClass::Interior);
    // A small change of path length is the same surface; sky beside a surface is a seam.
    p[at(3, 1) * 2] = 10.5f;
    EXPECT_EQ(classifyPixel(tech, ref, p, at(3, 2)), ErrorClass::Interior);
    p[at(3, 1) * 2] = 0.0f;
    EXPECT_EQ(classifyPixel(tech, ref, p, at(3, 2)), ErrorClass::SilhouetteSeam);
}

TEST(ErrorBreakdown, SharesOfTheWorstPixelsAndOfEachClass) {
    FloatImage ref = reflection(ppr::gpu::kReflectionHit);
    setAlpha(ref, 8, 6, ppr::gpu::kReflectionNone);  // 62 scored pixels
    const Rgba8Image truth = grey(100);
    Rgba8Image image = grey(100);
    setGrey(image, 4, 3, 100 + 30);  // one interior pixel carries 9/10 of the error
    setGrey(image, 0, 0, 100 + 10);  // one border pixel the rest
    setGrey(image, 8, 6, 0);         // not scored: ignored
    const ErrorBreakdown b = breakdownErrors(image, truth, FloatImage{}, ref, paths(5.0f));
    EXPECT_EQ(b.scoredPixels, 62u);
    EXPECT_TRUE(b.pathKnown);
    EXPECT_NEAR(b.squaredError, 3.0 * (30.0 * 30.0 + 10.0 * 10.0) / (255.0 * 255.0), 1e-12);
    EXPECT_NEAR(b.worst1PercentShare, 0.9, 1e-12);   // ceil(0.62) = 1 pixel
    EXPECT_NEAR(b.worst10PercentShare, 1.0, 1e-12);  // 7 pixels hold both
    EXPECT_NEAR(b.share[size_t(ErrorClass::Interior)], 0.9, 1e-12);
    EXPECT_NEAR(b.share[size_t(ErrorClass::ReflectorEdge)], 0.1, 1e-12);
    uint64_t counted = 0;
    for (uint64_t n : b.pixels) counted += n;
    EXPECT_EQ(counted, 62u);

    const ErrorBreakdown exact = breakdownErrors(truth, truth, FloatImage{}, ref, {});
    EXPECT_EQ(exact.squaredError, 0.0);
    EXPECT_EQ(exact.worst1PercentShare, 0.0);
    EXPECT_FALSE(exact.pathKnown);
}

TEST(ErrorBreakdown, RejectsMismatchedSizes) {
    const FloatImage ref = reflection(ppr::gpu::kReflectionHit);
    const Rgba8Image img = grey(0);
    Rgba8Image small{2, 2, std::vector<uint8_t>(16, 0)};
    EXPECT_THROW(breakdownErrors(small, img, FloatImage{}, ref, {}), std::invalid_argument);
    EXPECT_THROW(breakdownErrors(img, img, FloatImage{}, ref, std::vector<float>(3, 0.0f)), std::invalid_argument);
    FloatImage wrong{2, 2, std::vector<float>(16, 0.0f)};
    EXPECT_THROW(breakdownErrors(img, img, wrong, ref, {}), std::invalid_argument);
    EXPECT_THROW(errorClassImage(ref, {}, small), std::invalid_argument);
}

TEST(ErrorBreakdown, ClassImageColoursScoredPixelsOnly) {
    FloatImage ref = reflection(ppr::gpu::kReflectionNone);
    setAlpha(ref, 4, 3, ppr::gpu::kReflectionHit);
    const Rgba8Image out = errorClassImage(ref, {}, grey(200));
    EXPECT_EQ(out.pixels[at(0, 0) * 4], 50);  // dimmed context
    const uint8_t* p = &out.pixels[at(4, 3) * 4];
    EXPECT_EQ(std::vector<uint8_t>(p, p + 3), (std::vector<uint8_t>{255, 60, 60}));  // a reflector edge (its neighbours are not reflectors)
    for (ErrorClass c : {ErrorClass::ReflectorEdge, ErrorClass::Interior}) EXPECT_NE(std::string(errorClassName(c)), "");
}
