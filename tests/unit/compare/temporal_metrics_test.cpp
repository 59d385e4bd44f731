// Camera-path scores: frame-to-frame change, the means and flicker after convergence.
#include "metrics/temporal_metrics.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

using namespace ppr::app;

namespace {

ppr::util::Rgba8Image flat(uint8_t value, uint8_t alpha = 255) {
    ppr::util::Rgba8Image img;
    img.width = 3;
    img.height = 2;
    img.pixels.assign(3 * 2 * 4, value);
    for (size_t i = 3; i < img.pixels.size(); i += 4) img.pixels[i] = alpha;
    return img;
}

TEST(TemporalMetrics, ChangeIsTheMeanAbsoluteRgbDifferenceInLevels) {
    EXPECT_EQ(meanAbsoluteChange(flat(10), flat(10, 0)), 0.0);  // alpha is not a colour
    EXPECT_DOUBLE_EQ(meanAbsoluteChange(flat(10), flat(14)), 4.0);
    EXPECT_DOUBLE_EQ(meanAbsoluteChange(flat(14), flat(10)), 4.0);
    ppr::util::Rgba8Image one = flat(0);
    one.pixels[0] = 60;  // one channel of one pixel of six: 60 / 18
    EXPECT_DOUBLE_EQ(meanAbsoluteChange(flat(0), one), 60.0 / 18.0);
    ppr::util::Rgba8Image wide = flat(0);
    wide.width = 6;
    wide.height = 1;
    EXPECT_THROW(meanAbsoluteChange(flat(0), wide), std::invalid_argument);
}

TEST(TemporalMetrics, ExcessChangeIsTheChangeTheReferenceDoesNotMake) {
    // Unchanged reference: the plain change, bit for bit (a still scene's flicker as before).
    EXPECT_EQ(meanAbsoluteExcessChange(flat(10), flat(14), flat(50), flat(50)), meanAbsoluteChange(flat(10), flat(14)));
    // The image changes as the reference does (real motion): no flicker.
    EXPECT_EQ(meanAbsoluteExcessChange(flat(14), flat(10), flat(54), flat(50)), 0.0);
    // Against the reference's change: 4 up where it went 4 down is 8 levels of flicker.
    EXPECT_DOUBLE_EQ(meanAbsoluteExcessChange(flat(14), flat(10), flat(46), flat(50)), 8.0);
    ppr::util::Rgba8Image wide = flat(0);
    wide.width = 6;
    wide.height = 1;
    EXPECT_THROW(meanAbsoluteExcessChange(flat(0), flat(0), wide, flat(0)), std::invalid_argument);
}

TEST(TemporalMetrics, MeansOverEveryFrameFlickerOnlyWhenStillAndSettled) {
    std::vector<TemporalFrame> frames;
    // Flicker counts the change the reference does not make (excessChange), not the raw change.
    for (int i = 0; i < 40; ++i) frames.push_back({30.0 + i % 2, 20.0, 5.0, i < 16 ? 9.0 : 1.0, 25.0 + i % 4});
    const TemporalSummary moving = summarizeTemporal(frames, false, 16);
    EXPECT_DOUBLE_EQ(moving.psnrDbMean, 30.5);
    EXPECT_DOUBLE_EQ(moving.reflectorPsnrDbMean, 20.0);
    EXPECT_DOUBLE_EQ(moving.scoredPsnrDbMean, 26.5);
    EXPECT_FALSE(moving.flicker.has_value());
    EXPECT_EQ(moving.frames, 40u);
    const TemporalSummary still = summarizeTemporal(frames, true, 16);
    EXPECT_EQ(still.settledFrom, 16u);
    EXPECT_DOUBLE_EQ(*still.flicker, 1.0);  // the first 16 frames' large changes are convergence
    // A short run settles at half its length; one frame has nothing to compare with.
    EXPECT_EQ(summarizeTemporal(std::vector<TemporalFrame>(10), true, 16).settledFrom, 5u);
    EXPECT_EQ(*summarizeTemporal(std::vector<TemporalFrame>(1), true, 16).flicker, 0.0);
    EXPECT_THROW(summarizeTemporal({}, true, 16), std::invalid_argument);
}

}  // namespace

namespace {

TEST(TemporalMetrics, HeatMapColoursMaskPixelsByTheirDisplayErrorAndDimsTheRest) {
    ppr::util::Rgba8Image image = flat(200), reference = flat(200);
    image.pixels[0] = 200 - 64;  // pixel 0: an error of 64 levels (a quarter: full scale, white)
    image.pixels[4 + 1] = 200 - 21;  // pixel 1: 21 levels, a third of full scale: red
    FloatImage mask;
    mask.width = 3;
    mask.height = 2;
    mask.rgba.assign(3 * 2 * 4, 0.0f);
    mask.rgba[3] = mask.rgba[4 + 3] = mask.rgba[8 + 3] = 1.0f;  // pixels 0..2 are reflector pixels
    const ppr::util::Rgba8Image heat = displayErrorHeatMap(image, reference, mask);
    EXPECT_EQ(heat.pixels[0], 255);
    EXPECT_EQ(heat.pixels[2], 255);
    EXPECT_GT(heat.pixels[4], 240);  // red
    EXPECT_LT(heat.pixels[5], 15);
    EXPECT_EQ(heat.pixels[8], 0);  // no error: black
    EXPECT_EQ(heat.pixels[12], 50);  // outside the mask: the image at 25 %
    EXPECT_EQ(heat.pixels[15], 255);
    mask.width = 2;
    EXPECT_THROW(displayErrorHeatMap(image, reference, mask), std::invalid_argument);
}

}  // namespace
