// The viewer's render scale: the render extent for a window, and which render pixel a click lands on.
#include "render/render_scale.hpp"

#include <gtest/gtest.h>

namespace ppr::app {
namespace {

TEST(RenderScale, AutoRendersAtHalfSizeOnACpuDeviceAndFullSizeOnAGpu) {
    EXPECT_FLOAT_EQ(defaultRenderScale("cpu"), 0.5f);
    EXPECT_FLOAT_EQ(defaultRenderScale("discrete"), 1.0f);
    EXPECT_FLOAT_EQ(defaultRenderScale("integrated"), 1.0f);
    EXPECT_FLOAT_EQ(defaultRenderScale("virtual"), 1.0f);
    EXPECT_FLOAT_EQ(defaultRenderScale(""), 1.0f);
    EXPECT_EQ(scaledExtent({1280, 720}, defaultRenderScale("cpu")).width, 640u);
}

TEST(RenderScale, ScaledExtentRoundsEachSideAndKeepsAPixel) {
    EXPECT_EQ(scaledExtent({1280, 720}, 1.0f).width, 1280u);
    EXPECT_EQ(scaledExtent({1280, 720}, 1.0f).height, 720u);
    EXPECT_EQ(scaledExtent({1280, 720}, 0.5f).width, 640u);
    EXPECT_EQ(scaledExtent({1280, 720}, 0.5f).height, 360u);
    EXPECT_EQ(scaledExtent({1281, 721}, 0.5f).width, 641u);  // 640.5 rounds away from zero
    EXPECT_EQ(scaledExtent({1920, 1080}, 0.33f).width, 634u);
    EXPECT_EQ(scaledExtent({1920, 1080}, 0.33f).height, 356u);
    EXPECT_EQ(scaledExtent({3, 1}, kMinRenderScale).width, 1u);  // never 0: a 1-pixel frame is valid
    EXPECT_EQ(scaledExtent({3, 1}, kMinRenderScale).height, 1u);
}

TEST(RenderScale, EveryChoiceIsAValidScale) {
    EXPECT_EQ(kRenderScaleChoices.front(), 1.0f);  // the default: the window's own resolution
    for (float s : kRenderScaleChoices) {
        EXPECT_GE(s, kMinRenderScale);
        EXPECT_LE(s, 1.0f);
    }
}

TEST(RenderScale, AClickLandsOnTheRenderPixelUnderIt) {
    const VkExtent2D window{640, 360}, half{320, 180};
    EXPECT_EQ(renderPixelOf({0, 0}, window, half), glm::ivec2(0, 0));
    EXPECT_EQ(renderPixelOf({1, 1}, window, half), glm::ivec2(0, 0));
    EXPECT_EQ(renderPixelOf({2, 3}, window, half), glm::ivec2(1, 1));
    EXPECT_EQ(renderPixelOf({440, 212}, window, half), glm::ivec2(220, 106));
    EXPECT_EQ(renderPixelOf({639, 359}, window, half), glm::ivec2(319, 179));
    // At scale 1 every pixel maps to itself.
    for (int x : {0, 1, 317, 639}) EXPECT_EQ(renderPixelOf({x, 5}, window, window), glm::ivec2(x, 5));
    // Outside the window (a drag past its edge): clamped into the frame.
    EXPECT_EQ(renderPixelOf({-5, 400}, window, half), glm::ivec2(0, 179));
}

}  // namespace
}  // namespace ppr::app
