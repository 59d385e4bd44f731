// The viewer's A/B comparison with the planar ground truth, through the same renderer path the viewer
// uses (headless), with validation + synchronization validation on.
#include "gpu_test_util.hpp"

#include <cstring>

namespace ppr::test {
namespace {

constexpr VkExtent2D kSize{320, 180};

util::Rgba8Image renderFinal(GpuFixture& f, const std::string& technique, app::AbView ab, float split) {
    f.headless->setTechnique(technique);
    f.headless->setAb(ab, split);
    util::Rgba8Image img = f.headless->capture(f.camera("stairs"), kSize, 1).image;
    f.headless->setAb(app::AbView::Off, 0.5f);
    return img;
}

size_t differingPixels(const util::Rgba8Image& a, const util::Rgba8Image& b) {
    size_t n = 0;
    for (size_t i = 0; i < a.pixels.size(); i += 4) n += std::memcmp(&a.pixels[i], &b.pixels[i], 3) != 0;
    return n;
}

TEST(AbCompare, SplitShowsTheTechniqueLeftAndTheGroundTruthRight) {
    GpuFixture f;  // the stairs view: no glass pane in sight (its reflection is the technique's in both halves)
    const util::Rgba8Image ppr = renderFinal(f, "ppr", app::AbView::Off, 0.5f);
    const util::Rgba8Image planar = renderFinal(f, "planar", app::AbView::Off, 0.5f);
    ASSERT_GT(differingPixels(ppr, planar), 100u) << "the two techniques must differ for this test to mean anything";
    EXPECT_EQ(differingPixels(renderFinal(f, "ppr", app::AbView::Split, 1.0f), ppr), 0u) << "split at the right edge: all PPR";
    EXPECT_EQ(differingPixels(renderFinal(f, "ppr", app::AbView::Split, 0.0f), planar), 0u) << "split at the left edge: all planar";
    // Halfway: the left half is PPR's, the right half the reference's (the split line aside).
    const util::Rgba8Image half = renderFinal(f, "ppr", app::AbView::Split, 0.5f);
    size_t leftWrong = 0, rightWrong = 0;
    for (uint32_t y = 0; y < kSize.height; ++y)
        for (uint32_t x = 0; x < kSize.width; ++x) {
            const size_t i = (size_t(y) * kSize.width + x) * 4;
            if (x + 1 < kSize.width / 2) leftWrong += std::memcmp(&half.pixels[i], &ppr.pixels[i], 3) != 0;
            if (x > kSize.width / 2) rightWrong += std::memcmp(&half.pixels[i], &planar.pixels[i], 3) != 0;
        }
    EXPECT_EQ(leftWrong, 0u);
    EXPECT_EQ(rightWrong, 0u);
    EXPECT_EQ(f.ctx->validationErrors(), 0u);
}

TEST(AbCompare, ErrorHeatMapMarksTheScoredPixels) {
    GpuFixture f;
    const util::Rgba8Image ppr = renderFinal(f, "ppr", app::AbView::Off, 0.5f);
    const util::Rgba8Image heat = renderFinal(f, "ppr", app::AbView::ErrorHeat, 0.5f);
    // Everything changes: scored pixels show the error, the rest is dimmed.
    EXPECT_GT(differingPixels(heat, ppr), size_t(kSize.width) * kSize.height / 2);
    // Pure grey (the unscored reflector pixels) and heat colours (red ≥ green ≥ blue) appear.
    size_t grey = 0, hot = 0;
    for (size_t i = 0; i < heat.pixels.size(); i += 4) {
        const uint8_t r = heat.pixels[i], g = heat.pixels[i + 1], b = heat.pixels[i + 2];
        if (r == g && g == b && r > 100 && r < 160) ++grey;
        if (r > 60 && r >= g && g >= b && b < 40) ++hot;
    }
    EXPECT_GT(hot, 50u);
    EXPECT_GT(grey + hot, 500u);
    // The planar technique has nothing to compare with: A/B is ignored.
    EXPECT_EQ(differingPixels(renderFinal(f, "planar", app::AbView::ErrorHeat, 0.5f), renderFinal(f, "planar", app::AbView::Off, 0.5f)), 0u);
    EXPECT_EQ(f.ctx->validationErrors(), 0u);
}

}  // namespace
}  // namespace ppr::test
