// Bench charts: image size, series colours, where points land on linear and log axes, tick
// choice and labels, input validation, and side-by-side composition.
#include "bench/bench_plot.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

using namespace ppr::app;
using ppr::util::Rgba8Image;

namespace {

bool hasRgb(const Rgba8Image& img, int x, int y, std::array<uint8_t, 3> c) {
    const uint8_t* p = &img.pixels[(size_t(y) * img.width + x) * 4];
    return p[0] == c[0] && p[1] == c[1] && p[2] == c[2] && p[3] == 255;
}

int countRgb(const Rgba8Image& img, std::array<uint8_t, 3> c) {
    int n = 0;
    for (uint32_t y = 0; y < img.height; ++y)
        for (uint32_t x = 0; x < img.width; ++x) n += hasRgb(img, int(x), int(y), c);
    return n;
}

// Every point of every series has its series' colour at the pixel the frame maps it to (each
// point's marker is drawn last over its own position; the specs below keep points apart).
void expectPointsAtFramePixels(const PlotSpec& spec, const Rgba8Image& img, const PlotFrame& f) {
    for (size_t i = 0; i < spec.series.size(); ++i)
        for (size_t k = 0; k < spec.series[i].x.size(); ++k) {
            const long x = std::lround(f.x.toPixel(spec.series[i].x[k]));
            const long y = std::lround(f.y.toPixel(spec.series[i].y[k]));
            EXPECT_TRUE(hasRgb(img, int(x), int(y), plotSeriesColour(i)))
                << "series " << i << " point " << k << " at pixel " << x << "," << y;
        }
}

PlotSpec benchLike() {
    PlotSpec spec{"projection pass", "reflectors N", "ms", true, false, {}};
    PlotSeries on{"tiles=1", {}, {}}, off{"tiles=0", {}, {}};
    for (double n : {1.0, 4.0, 16.0, 64.0, 256.0, 1024.0}) {
        on.x.push_back(n), on.y.push_back(10);
        off.x.push_back(n), off.y.push_back(10 + 890 * (n - 1) / 1023 + 20);  // off the flat line
    }
    spec.series = {on, off};
    return spec;
}

}  // namespace

TEST(BenchPlot, AxisMappingLinear) {
    const PlotAxis x{0, 10, false, 100, 200, {}};
    EXPECT_DOUBLE_EQ(x.toPixel(0), 100);
    EXPECT_DOUBLE_EQ(x.toPixel(5), 150);
    EXPECT_DOUBLE_EQ(x.toPixel(10), 200);
    const PlotAxis y{0, 1000, false, 400, 100, {}};  // grows upwards
    EXPECT_DOUBLE_EQ(y.toPixel(0), 400);
    EXPECT_DOUBLE_EQ(y.toPixel(250), 325);
    EXPECT_DOUBLE_EQ(y.toPixel(1000), 100);
}

TEST(BenchPlot, AxisMappingLog) {
    const PlotAxis x{1, 1024, true, 0, 100, {}};
    EXPECT_DOUBLE_EQ(x.toPixel(1), 0);
    EXPECT_DOUBLE_EQ(x.toPixel(32), 50);  // half of the 10 doublings
    EXPECT_DOUBLE_EQ(x.toPixel(4), 20);
    EXPECT_DOUBLE_EQ(x.toPixel(1024), 100);
    const PlotAxis y{0.1, 1000, true, 400, 0, {}};
    EXPECT_NEAR(y.toPixel(10), 200, 1e-9);
    EXPECT_NEAR(y.toPixel(1), 300, 1e-9);
}

TEST(BenchPlot, ImageHasRequestedSizeAndIsOpaque) {
    for (auto [w, h] : {std::pair{720u, 460u}, std::pair{320u, 220u}}) {
        const Rgba8Image img = renderPlot(benchLike(), w, h);
        ASSERT_EQ(img.width, w);
        ASSERT_EQ(img.height, h);
        ASSERT_EQ(img.pixels.size(), size_t(w) * h * 4);
        for (size_t i = 0; i < size_t(w) * h; ++i) ASSERT_EQ(img.pixels[i * 4 + 3], 255) << "pixel " << i;
    }
}

TEST(BenchPlot, EachSeriesColourAppears) {
    PlotSpec spec{"three", "x", "y", false, false, {}};
    spec.series = {{"a", {0, 1, 2}, {1, 2, 3}}, {"b", {0, 1, 2}, {3, 1, 2}}, {"c", {0, 2}, {5, 5}}};
    const Rgba8Image img = renderPlot(spec, 640, 400);
    for (size_t i = 0; i < spec.series.size(); ++i) EXPECT_GT(countRgb(img, plotSeriesColour(i)), 50) << "series " << i;
    // The palette colours are distinct, and none is the background.
    for (size_t i = 0; i < 10; ++i) {
        EXPECT_NE(plotSeriesColour(i), (std::array<uint8_t, 3>{255, 255, 255}));
        for (size_t j = 0; j < i; ++j) EXPECT_NE(plotSeriesColour(i), plotSeriesColour(j));
    }
}

TEST(BenchPlot, LinearPointsLandOnTheirPixels) {
    PlotSpec spec{"linear", "fraction", "ms", false, false, {}};
    spec.series = {{"on", {0.1, 0.5, 1.0}, {40, 70, 100}}, {"off", {0.1, 0.5, 1.0}, {110, 110, 110}}};
    const PlotFrame f = plotFrame(spec, 640, 400);
    // The y axis starts at 0 although the data starts at 40; both ranges cover the data.
    EXPECT_EQ(f.y.lo, 0);
    EXPECT_GE(f.y.hi, 110);
    EXPECT_LE(f.x.lo, 0.1);
    EXPECT_GE(f.x.hi, 1.0);
    EXPECT_GT(f.y.pixelLo, f.y.pixelHi);  // up is smaller y
    // The plot area lies inside the image with room for labels on every side.
    EXPECT_GT(f.x.pixelLo, 20);
    EXPECT_LT(f.x.pixelHi, 640 - 5);
    EXPECT_GT(f.y.pixelHi, 20);
    EXPECT_LT(f.y.pixelLo, 400 - 20);
    // Ticks are within range, ascending, and include both ends for a linear axis.
    ASSERT_GE(f.y.ticks.size(), 3u);
    EXPECT_EQ(f.y.ticks.front(), f.y.lo);
    EXPECT_DOUBLE_EQ(f.y.ticks.back(), f.y.hi);
    for (size_t i = 1; i < f.y.ticks.size(); ++i) EXPECT_LT(f.y.ticks[i - 1], f.y.ticks[i]);
    expectPointsAtFramePixels(spec, renderPlot(spec, 640, 400), f);
}

TEST(BenchPlot, LogPointsLandOnTheirPixels) {
    const PlotSpec spec = benchLike();
    const PlotFrame f = plotFrame(spec, 720, 460);
    // Powers of 2 data on a log axis: the range is exactly 1..1024 and every tick a power of 2.
    EXPECT_EQ(f.x.lo, 1);
    EXPECT_EQ(f.x.hi, 1024);
    ASSERT_GE(f.x.ticks.size(), 3u);
    for (double t : f.x.ticks) {
        int e = 0;
        EXPECT_EQ(std::frexp(t, &e), 0.5) << t;
    }
    // Equal ratios are equal distances: 1 -> 32 -> 1024.
    EXPECT_NEAR(f.x.toPixel(32) - f.x.toPixel(1), f.x.toPixel(1024) - f.x.toPixel(32), 1e-9);
    EXPECT_NEAR(f.x.toPixel(32), (f.x.pixelLo + f.x.pixelHi) / 2, 1e-9);
    const Rgba8Image img = renderPlot(spec, 720, 460);
    expectPointsAtFramePixels(spec, img, f);
    // Markers are centred on their point to the pixel: the flat series' disc (clear of the other
    // series from N = 64 on) spans as far above as below the mapped y in its column.
    for (size_t k = 3; k < spec.series[0].x.size(); ++k) {
        const int x = int(std::lround(f.x.toPixel(spec.series[0].x[k])));
        const int y = int(std::lround(f.y.toPixel(spec.series[0].y[k])));
        int up = 0, down = 0;
        while (hasRgb(img, x, y - up - 1, plotSeriesColour(0))) ++up;
        while (hasRgb(img, x, y + down + 1, plotSeriesColour(0))) ++down;
        EXPECT_EQ(up, down) << "point " << k;
        EXPECT_GE(up, 2) << "point " << k;
    }
}

TEST(BenchPlot, LogAxesWithOtherValuesUsePowersOf10) {
    PlotSpec spec{"log-log", "N", "ms", true, true, {}};
    spec.series = {{"a", {1, 3, 10, 30, 100, 300, 1000}, {0.2, 0.6, 2, 6, 20, 60, 200}}};
    const PlotFrame f = plotFrame(spec, 640, 400);
    EXPECT_LE(f.y.lo, 0.2);
    EXPECT_GT(f.y.lo, 0);  // no zero on a log axis
    EXPECT_GE(f.y.hi, 200);
    for (const PlotAxis* a : {&f.x, &f.y}) {
        ASSERT_GE(a->ticks.size(), 2u);
        for (double t : a->ticks) {
            const double m = t / std::pow(10.0, std::floor(std::log10(t) + 1e-9));
            EXPECT_TRUE(std::abs(m - 1) < 1e-9 || std::abs(m - 2) < 1e-9 || std::abs(m - 5) < 1e-9) << t;
        }
    }
    expectPointsAtFramePixels(spec, renderPlot(spec, 640, 400), f);
}

TEST(BenchPlot, TickLabelsAreCompact) {
    EXPECT_EQ(formatTick(0), "0");
    EXPECT_EQ(formatTick(-0.0), "0");
    EXPECT_EQ(formatTick(1), "1");
    EXPECT_EQ(formatTick(16), "16");
    EXPECT_EQ(formatTick(0.5), "0.5");
    EXPECT_EQ(formatTick(12.5), "12.5");
    EXPECT_EQ(formatTick(0.1 + 0.2), "0.3");
    EXPECT_EQ(formatTick(1024), "1024");
    EXPECT_EQ(formatTick(1000), "1k");
    EXPECT_EQ(formatTick(2500), "2.5k");
    EXPECT_EQ(formatTick(16384), "16384");
    EXPECT_EQ(formatTick(1e6), "1M");
    EXPECT_EQ(formatTick(-250), "-250");
}

TEST(BenchPlot, BadInputThrows) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    auto throws = [](const PlotSpec& spec, uint32_t w = 640, uint32_t h = 400) {
        EXPECT_THROW(renderPlot(spec, w, h), std::invalid_argument);
        EXPECT_THROW(plotFrame(spec, w, h), std::invalid_argument);
    };
    throws(PlotSpec{"none", "x", "y", false, false, {}});
    throws(PlotSpec{"empty", "x", "y", false, false, {{"a", {}, {}}}});
    throws(PlotSpec{"lengths", "x", "y", false, false, {{"a", {1, 2}, {1}}}});
    throws(PlotSpec{"nan", "x", "y", false, false, {{"a", {1, nan}, {1, 2}}}});
    throws(PlotSpec{"inf", "x", "y", false, false, {{"a", {1, 2}, {1, inf}}}});
    throws(PlotSpec{"logx0", "x", "y", true, false, {{"a", {0, 2}, {1, 2}}}});
    throws(PlotSpec{"logy-", "x", "y", false, true, {{"a", {1, 2}, {-1, 2}}}});
    // A good second series does not hide a bad one.
    throws(PlotSpec{"second", "x", "y", false, false, {{"a", {1, 2}, {1, 2}}, {"b", {1}, {}}}});
    throws(benchLike(), 60, 40);  // no room for a plot area
    // Zero on a linear axis, and a single point, are fine.
    EXPECT_NO_THROW(renderPlot(PlotSpec{"ok", "x", "y", false, false, {{"a", {0}, {0}}}}, 320, 200));
}

TEST(BenchPlot, SideBySideWidthsAddUp) {
    const Rgba8Image a = renderPlot(benchLike(), 300, 240);
    const Rgba8Image b = renderPlot(benchLike(), 420, 240);
    const Rgba8Image both = sideBySide({a, b});
    ASSERT_EQ(both.width, 720u);
    ASSERT_EQ(both.height, 240u);
    ASSERT_EQ(both.pixels.size(), size_t(720) * 240 * 4);
    // Each chart's rows are copied unchanged at its offset.
    for (uint32_t y : {0u, 100u, 239u}) {
        EXPECT_TRUE(std::equal(&a.pixels[size_t(y) * 300 * 4], &a.pixels[size_t(y + 1) * 300 * 4],
                               &both.pixels[size_t(y) * 720 * 4]));
        EXPECT_TRUE(std::equal(&b.pixels[size_t(y) * 420 * 4], &b.pixels[size_t(y + 1) * 420 * 4],
                               &both.pixels[(size_t(y) * 720 + 300) * 4]));
    }
    EXPECT_THROW(sideBySide({}), std::invalid_argument);
    EXPECT_THROW(sideBySide({a, renderPlot(benchLike(), 300, 250)}), std::invalid_argument);
}

// A compare path run plots one series per row, whose names are the user's (`ssr-brute@taa=1,...`):
// the legend wraps into as many rows as they need, and plotHeightFor grows the image so that the plot
// area keeps its height, where a fixed 400 px left no room and the run ended in an error.
TEST(BenchPlot, HeightForKeepsThePlotAreaWhateverTheLegend) {
    const PlotSpec few = benchLike();
    EXPECT_EQ(plotHeightFor(few, 640, 400, 200), 400u);  // two short names: the usual size
    PlotSpec many{"whole frame vs 16x supersampled planar", "frame", "PSNR dB", false, false, {}};
    for (int i = 0; i < 12; ++i)
        many.series.push_back({"ssr-brute@taa=1,taa_still_spread=0,variant_" + std::to_string(i), {0, 1, 2}, {10.0 * i, 10.0 * i + 3, 10.0 * i + 6}});  // apart: markers do not overlap
    EXPECT_THROW(renderPlot(many, 640, 400), std::invalid_argument);
    const uint32_t height = plotHeightFor(many, 640, 400, 200);
    EXPECT_GT(height, 400u);
    const Rgba8Image img = renderPlot(many, 640, height);
    EXPECT_EQ(img.height, height);
    const PlotFrame f = plotFrame(many, 640, height);
    EXPECT_GE(f.y.pixelLo - f.y.pixelHi, 200.0);  // y runs up: pixelLo is the bottom
    expectPointsAtFramePixels(many, img, f);
    // Small images keep the small text scale; the height still fits.
    EXPECT_NO_THROW(renderPlot(many, 320, plotHeightFor(many, 320, 200, 100)));
}
