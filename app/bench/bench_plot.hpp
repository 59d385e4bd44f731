#pragma once
// Line charts as PNG for `ppr bench` (docs/performance.md): there is no plotting library on the
// build machines, so this draws axes, ticks, series and a legend itself, text with stb_easy_font.
#include "util/image_io.hpp"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace ppr::app {

struct PlotSeries {
    std::string name;
    std::vector<double> x, y;  // same length; points are joined in this order
};

struct PlotSpec {
    std::string title, xLabel, yLabel;
    // Log axes get ticks at powers of 2 when every value on that axis is one (reflector counts
    // 1..1024), otherwise at powers of 10 (with 2 and 5 in between while that fits).
    bool logX = false, logY = false;
    std::vector<PlotSeries> series;
};

// One axis of a chart: maps a data value to a pixel coordinate, lo -> pixelLo and hi -> pixelHi,
// linear in the value or, for a log axis, in its logarithm. pixelHi < pixelLo is how the y axis
// grows upwards. Values outside [lo, hi] map outside [pixelLo, pixelHi]; a log axis needs v > 0.
struct PlotAxis {
    double lo = 0, hi = 1;
    bool log = false;
    double pixelLo = 0, pixelHi = 1;
    std::vector<double> ticks;  // grid lines and labels, ascending, within [lo, hi]

    double toPixel(double v) const;
};

// The axes renderPlot uses for `spec` at this size; the plot area is the pixel ranges of x and y.
// A point (x, y) is drawn centred on pixel (lround(x.toPixel(x)), lround(y.toPixel(y))).
struct PlotFrame {
    PlotAxis x, y;
};
PlotFrame plotFrame(const PlotSpec& spec, uint32_t width, uint32_t height);

// Tick label text: at most 4 significant digits, no trailing zeros, k / M for whole multiples of
// 1000 / 1e6 with at most two decimals: 0, 0.5, 12.5, 16, 1024, 1k, 2.5k, 1M.
std::string formatTick(double v);

// Colour of series i (RGB). Ten distinct colours, then they repeat.
std::array<uint8_t, 3> plotSeriesColour(size_t i);

// One opaque chart of width x height pixels on white: a title, a legend strip under it (outside
// the plot area, so it never covers data), grid, axes with ticks and labels, and per series a
// 2-pixel line in its colour with a marker (shape cycles per series) on every point. The y axis
// starts at 0 (or below, for negative data) unless logY; axis ranges are widened to whole ticks.
// Throws std::invalid_argument on no series, a series without points, mismatched x/y lengths,
// non-finite values, values <= 0 on a log axis, or a size too small for the plot area.
util::Rgba8Image renderPlot(const PlotSpec& spec, uint32_t width, uint32_t height);

// The least height, at least `minHeight`, at which renderPlot(spec, width, height) leaves a plot area
// `plotAreaHeight` pixels tall whatever rows the legend wraps into: for charts whose series are the
// user's (a compare row per technique variant, with long names).
uint32_t plotHeightFor(const PlotSpec& spec, uint32_t width, uint32_t minHeight, uint32_t plotAreaHeight);

// Charts placed left to right with no gap (each has its own margins): the width is the sum of
// the widths. Throws std::invalid_argument on no charts, differing heights, or pixels that do not
// match a chart's size.
util::Rgba8Image sideBySide(const std::vector<util::Rgba8Image>& charts);

}  // namespace ppr::app
