#include "bench/bench_plot.hpp"

#include "metrics/contact_sheet.hpp"  // drawText, textWidth

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <stdexcept>

namespace ppr::app {

namespace {

using Rgb = std::array<uint8_t, 3>;

constexpr Rgb kBackground{255, 255, 255};
constexpr Rgb kGrid{228, 228, 228};
constexpr Rgb kAxis{80, 80, 80};
constexpr Rgb kText{25, 25, 25};
// Tableau 10: distinguishable from each other on white, also for the common colour-vision deficiencies.
constexpr Rgb kPalette[] = {{31, 119, 180}, {255, 127, 14}, {44, 160, 44},   {214, 39, 40},  {148, 103, 189},
                            {140, 86, 75},  {227, 119, 194}, {127, 127, 127}, {188, 189, 34}, {23, 190, 207}};
constexpr size_t kPaletteSize = sizeof(kPalette) / sizeof(kPalette[0]);

// ---- pixels -------------------------------------------------------------------------------------

void setPixel(util::Rgba8Image& img, int x, int y, Rgb c) {
    if (x < 0 || y < 0 || x >= static_cast<int>(img.width) || y >= static_cast<int>(img.height)) return;
    uint8_t* p = &img.pixels[(size_t(y) * img.width + x) * 4];
    p[0] = c[0], p[1] = c[1], p[2] = c[2], p[3] = 255;
}

void fillRect(util::Rgba8Image& img, int x0, int y0, int x1, int y1, Rgb c) {  // half-open
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) setPixel(img, x, y, c);
}

// Bresenham, stamping a thickness x thickness square at every step: enough for 2-pixel chart lines.
void drawLine(util::Rgba8Image& img, int x0, int y0, int x1, int y1, int thickness, Rgb c) {
    const int dx = std::abs(x1 - x0), dy = -std::abs(y1 - y0);
    const int sx = x0 < x1 ? 1 : -1, sy = y0 < y1 ? 1 : -1;
    const int o = thickness / 2;
    for (int err = dx + dy;;) {
        fillRect(img, x0 - o, y0 - o, x0 - o + thickness, y0 - o + thickness, c);
        if (x0 == x1 && y0 == y1) break;
        const int e2 = 2 * err;
        if (e2 >= dy) err += dy, x0 += sx;
        if (e2 <= dx) err += dx, y0 += sy;
    }
}

// Marker shapes cycle per series so that series stay apart in greyscale print too. Every shape
// covers its centre pixel (the tests look for the series colour there).
void drawMarker(util::Rgba8Image& img, int cx, int cy, int r, size_t shape, Rgb c) {
    for (int dy = -r; dy <= r; ++dy)
        for (int dx = -r; dx <= r; ++dx) {
            bool inside = false;
            switch (shape % 4) {
                case 0: inside = dx * dx + dy * dy <= r * r + r; break;               // disc
                case 1: inside = std::abs(dx) < r && std::abs(dy) < r; break;         // square
                case 2: inside = 2 * std::abs(dx) <= dy + r; break;                  // triangle, apex up
                case 3: inside = std::abs(dx) + std::abs(dy) <= r; break;             // diamond
            }
            if (inside) setPixel(img, cx + dx, cy + dy, c);
        }
}

// A white halo first keeps markers readable where another series' line crosses them.
void drawHaloMarker(util::Rgba8Image& img, int cx, int cy, int r, size_t shape, Rgb c) {
    drawMarker(img, cx, cy, r + 1, shape, kBackground);
    drawMarker(img, cx, cy, r, shape, c);
}

void text(util::Rgba8Image& img, int x, int y, const std::string& s, int scale, Rgb c) {
    drawText(img, x, y, s, scale, c[0], c[1], c[2]);
}

// Text reading bottom to top, its box (lineHeight x width) with the top-left corner at (x, y):
// drawn upright into a transparent scratch image, then copied turned 90 degrees anticlockwise.
void textUp(util::Rgba8Image& img, int x, int y, const std::string& s, int scale, Rgb c) {
    const int w = textWidth(s, scale), h = 12 * scale;
    if (w <= 0) return;
    util::Rgba8Image scratch{uint32_t(w), uint32_t(h), std::vector<uint8_t>(size_t(w) * h * 4, 0)};
    text(scratch, 0, 0, s, scale, c);
    for (int ty = 0; ty < h; ++ty)
        for (int tx = 0; tx < w; ++tx)
            if (scratch.pixels[(size_t(ty) * w + tx) * 4 + 3]) setPixel(img, x + ty, y + (w - 1 - tx), c);
}

// ---- ticks --------------------------------------------------------------------------------------

struct TickSet {
    double lo, hi;  // the axis range: whole ticks around the data
    std::vector<double> ticks;
};

// Smallest 1, 2, 2.5, 5 x 10^k step >= v.
double niceAtLeast(double v) {
    const double mag = std::pow(10.0, std::floor(std::log10(v)));
    for (double m : {1.0, 2.0, 2.5, 5.0})
        if (m * mag >= v * (1 - 1e-9)) return m * mag;
    return 10 * mag;
}

// Candidate tick sets for a linear axis over [lo, hi] (lo < hi), densest first.
std::vector<TickSet> linearCandidates(double lo, double hi) {
    std::vector<TickSet> out;
    for (double step = niceAtLeast((hi - lo) / 20);; step = niceAtLeast(step * 1.001)) {
        // Ticks are integer multiples of the step, computed as k * step so that 0 is exactly 0.
        const double kLo = std::floor(lo / step + 1e-9);
        const double kHi = std::max(std::ceil(hi / step - 1e-9), kLo + 1);
        TickSet t{kLo * step, kHi * step, {}};
        for (double k = kLo; k <= kHi; ++k) t.ticks.push_back(k * step);
        out.push_back(std::move(t));
        if (kHi - kLo <= 1) return out;
    }
}

// Candidate tick sets for a log axis over powers of 2 (0 < lo <= hi, both powers of 2), densest
// first: every 1, 2, 3... exponents, the range widened to whole steps (exact for 1, 4, ..., 1024).
std::vector<TickSet> log2Candidates(double lo, double hi) {
    const double eLo = std::log2(lo), eHi = std::max(std::log2(hi), eLo + 1);
    std::vector<TickSet> out;
    for (double k = 1;; ++k) {
        const double n = std::ceil((eHi - eLo) / k);
        TickSet t{lo, std::exp2(eLo + n * k), {}};
        for (double i = 0; i <= n; ++i) t.ticks.push_back(std::exp2(eLo + i * k));
        out.push_back(std::move(t));
        if (n <= 1) return out;
    }
}

// Candidate tick sets for a base-10 log axis over [lo, hi] (0 < lo <= hi), densest first. Widening
// the range to whole decades could waste most of a decade (1..1024 would run to 10k), so it only
// goes out to the next 1, 2 or 5 x 10^k; ticks are the 1-2-5 values in range, then powers of 10
// every 1, 2, 3... decades (while at least two of them fall in range).
std::vector<TickSet> log10Candidates(double lo, double hi) {
    auto value125 = [](double i) {  // the i-th value of ..., 0.5, 1, 2, 5, 10, ... with value125(0) = 1
        const double e = std::floor(i / 3);
        const double m[] = {1.0, 2.0, 5.0};
        return m[static_cast<int>(i - 3 * e)] * std::pow(10.0, e);
    };
    // Start near the answer from log10, then step: log10 may be off by an ulp at exact powers.
    double iLo = std::floor(std::log10(lo)) * 3, iHi = std::ceil(std::log10(hi)) * 3;
    while (value125(iLo + 1) <= lo * (1 + 1e-9)) ++iLo;
    while (value125(iLo) > lo * (1 + 1e-9)) --iLo;
    while (value125(iHi - 1) >= hi * (1 - 1e-9)) --iHi;
    while (value125(iHi) < hi * (1 - 1e-9)) ++iHi;
    if (iLo == iHi) --iLo, ++iHi;  // a single 1-2-5 value: one step either side
    std::vector<TickSet> out;
    TickSet all{value125(iLo), value125(iHi), {}};
    for (double i = iLo; i <= iHi; ++i) all.ticks.push_back(value125(i));
    out.push_back(all);
    const double eLo = std::ceil(std::log10(all.lo) - 1e-9), eHi = std::floor(std::log10(all.hi) + 1e-9);
    for (double k = 1; eLo + k <= eHi; ++k) {
        TickSet t{all.lo, all.hi, {}};
        for (double e = eLo; e <= eHi + 1e-9; e += k) t.ticks.push_back(std::pow(10.0, e));
        out.push_back(std::move(t));
    }
    return out;
}

bool isPowerOf2(double v) {
    int e = 0;
    return std::frexp(v, &e) == 0.5;
}

// The axis over the given values: the densest candidate whose neighbouring labels (each
// `extent(tick)` pixels long along the axis) stay at least `gap` pixels apart, else the sparsest.
PlotAxis makeAxis(const std::vector<double>& values, bool log, bool fromZero, double pixelLo, double pixelHi,
                  const std::function<double(double)>& extent, double gap) {
    double lo = *std::min_element(values.begin(), values.end());
    double hi = *std::max_element(values.begin(), values.end());
    std::vector<TickSet> candidates;
    if (log) {
        const bool pow2 = std::all_of(values.begin(), values.end(), isPowerOf2);
        candidates = pow2 ? log2Candidates(lo, hi) : log10Candidates(lo, hi);
    } else {
        if (fromZero) lo = std::min(lo, 0.0), hi = std::max(hi, 0.0);
        if (lo == hi) {  // a single value: give it some room either side
            const double d = lo == 0 ? 1.0 : std::abs(lo) * 0.5;
            lo = fromZero && lo >= 0 ? 0.0 : lo - d;
            hi += d;
        }
        candidates = linearCandidates(lo, hi);
    }
    PlotAxis axis;
    for (TickSet& t : candidates) {
        axis = PlotAxis{t.lo, t.hi, log, pixelLo, pixelHi, std::move(t.ticks)};
        bool fits = true;
        for (size_t i = 0; i + 1 < axis.ticks.size() && fits; ++i) {
            const double apart = std::abs(axis.toPixel(axis.ticks[i + 1]) - axis.toPixel(axis.ticks[i]));
            fits = apart >= (extent(axis.ticks[i]) + extent(axis.ticks[i + 1])) / 2 + gap;
        }
        if (fits) break;
    }
    return axis;
}

// ---- layout -------------------------------------------------------------------------------------

void validate(const PlotSpec& spec) {
    if (spec.series.empty()) throw std::invalid_argument("plot '" + spec.title + "': no series");
    for (const PlotSeries& s : spec.series) {
        const std::string where = "plot '" + spec.title + "', series '" + s.name + "': ";
        if (s.x.empty()) throw std::invalid_argument(where + "no points");
        if (s.x.size() != s.y.size())
            throw std::invalid_argument(where + std::to_string(s.x.size()) + " x values but " +
                                        std::to_string(s.y.size()) + " y values");
        for (size_t i = 0; i < s.x.size(); ++i) {
            if (!std::isfinite(s.x[i]) || !std::isfinite(s.y[i]))
                throw std::invalid_argument(where + "point " + std::to_string(i) + " is not finite");
            if ((spec.logX && s.x[i] <= 0) || (spec.logY && s.y[i] <= 0))
                throw std::invalid_argument(where + "point " + std::to_string(i) + " is <= 0 on a log axis");
        }
    }
}

struct Layout {
    PlotFrame frame;
    int scale, lineH, capH, pad, gap, tickLen, markerR, swatchW;
    int plotL, plotT, plotR, plotB;  // plot area, inclusive
    int titleY;
    std::vector<std::array<int, 2>> legendPos;  // top-left of each series' legend entry
};

// Everything is sized from the text scale: 2x stb_easy_font glyphs (14 px capitals) for charts
// big enough to go into the docs, 1x for thumbnails.
Layout scaledLayout(uint32_t width, uint32_t height) {
    Layout L{};
    const int s = std::min(width, height) >= 360 ? 2 : 1;
    L.scale = s, L.lineH = 12 * s, L.capH = 7 * s, L.pad = 8 * s, L.gap = 4 * s, L.tickLen = 4 * s;
    L.markerR = 2 + s, L.swatchW = 20 * s;
    return L;
}

// The title, then the legend in rows of entries (swatch, name) wrapped to the image width: each
// entry's offset within the legend block, the block's widest row and where the plot area may begin.
struct LegendBlock {
    std::vector<std::array<int, 2>> rel;
    int y = 0, width = 0, plotTop = 0;
};
LegendBlock legendBlock(const PlotSpec& spec, const Layout& L, int W) {
    const int s = L.scale;
    LegendBlock b;
    b.y = L.pad + (spec.title.empty() ? 0 : L.lineH + L.gap);
    const int entrySpacing = 14 * s;
    int x = 0, rowY = 0;
    for (const PlotSeries& ser : spec.series) {
        const int w = L.swatchW + L.gap + textWidth(ser.name, s);
        if (x > 0 && x + w > W - 2 * L.pad) x = 0, rowY += L.lineH;
        b.rel.push_back({x, rowY});
        x += w + entrySpacing;
        b.width = std::max(b.width, x - entrySpacing);
    }
    b.plotTop = b.y + rowY + L.lineH + L.gap + L.capH / 2 + s;  // room for half of the top tick label
    return b;
}

// Below the plot area: the x ticks, their labels and the axis label.
int bottomMargin(const PlotSpec& spec, const Layout& L) { return L.pad + L.tickLen + L.gap + L.lineH + (spec.xLabel.empty() ? 0 : L.lineH); }

Layout computeLayout(const PlotSpec& spec, uint32_t width, uint32_t height) {
    validate(spec);
    Layout L = scaledLayout(width, height);
    const int s = L.scale;
    const int W = static_cast<int>(width), H = static_cast<int>(height);
    L.titleY = L.pad;
    const LegendBlock legend = legendBlock(spec, L, W);

    // Vertical extent first: the y ticks depend on the plot height, the left margin on their labels.
    L.plotT = legend.plotTop;
    L.plotB = H - 1 - bottomMargin(spec, L);
    if (L.plotB - L.plotT < 16) throw std::invalid_argument("plot '" + spec.title + "': image too small");
    std::vector<double> xs, ys;
    for (const PlotSeries& ser : spec.series)
        xs.insert(xs.end(), ser.x.begin(), ser.x.end()), ys.insert(ys.end(), ser.y.begin(), ser.y.end());
    const double capH = L.capH;
    L.frame.y = makeAxis(ys, spec.logY, true, L.plotB, L.plotT, [capH](double) { return capH; }, 1.5 * L.lineH);

    int yLabelW = 0;
    for (double t : L.frame.y.ticks) yLabelW = std::max(yLabelW, textWidth(formatTick(t), s));
    L.plotL = L.pad + (spec.yLabel.empty() ? 0 : L.lineH + L.gap) + yLabelW + L.gap + L.tickLen;
    L.plotR = W - 1 - L.pad - 12 * s;  // the last x label is centred on the edge: leave it two digits
    if (L.plotR - L.plotL < 16) throw std::invalid_argument("plot '" + spec.title + "': image too small");
    L.frame.x = makeAxis(xs, spec.logX, false, L.plotL, L.plotR,
                         [s](double t) { return double(textWidth(formatTick(t), s)); }, 18.0 * s);

    // Legend aligned with the plot area when it fits there, else with the image margin.
    const int legendX = L.plotL + legend.width <= W - L.pad ? L.plotL : L.pad;
    for (auto [ex, ey] : legend.rel) L.legendPos.push_back({legendX + ex, legend.y + ey});
    return L;
}

int px(double v) { return static_cast<int>(std::lround(v)); }

}  // namespace

double PlotAxis::toPixel(double v) const {
    // log2 so that powers of 2 on a powers-of-2 axis land exactly (the base cancels out).
    const double f = log ? (std::log2(v) - std::log2(lo)) / (std::log2(hi) - std::log2(lo)) : (v - lo) / (hi - lo);
    return pixelLo + f * (pixelHi - pixelLo);
}

uint32_t plotHeightFor(const PlotSpec& spec, uint32_t width, uint32_t minHeight, uint32_t plotAreaHeight) {
    uint32_t height = minHeight;
    for (int pass = 0; pass < 2; ++pass) {  // a taller image may take the larger text scale, whose legend is taller
        const Layout L = scaledLayout(width, height);
        const LegendBlock legend = legendBlock(spec, L, static_cast<int>(width));
        const int needed = legend.plotTop + static_cast<int>(plotAreaHeight) + 1 + bottomMargin(spec, L);
        height = std::max(height, static_cast<uint32_t>(needed));
    }
    return height;
}

PlotFrame plotFrame(const PlotSpec& spec, uint32_t width, uint32_t height) {
    return computeLayout(spec, width, height).frame;
}

std::string formatTick(double v) {
    if (v == 0) return "0";  // also -0
    char buf[64];
    const double a = std::abs(v);
    for (auto [unit, suffix] : {std::pair{1e6, "M"}, std::pair{1e3, "k"}}) {
        const double hundredths = v / unit * 100;
        if (a >= unit && std::abs(hundredths - std::round(hundredths)) < 1e-6) {
            std::snprintf(buf, sizeof buf, "%.6g%s", v / unit, suffix);
            return buf;
        }
    }
    // %.4g would switch to exponents from 10000 on; whole numbers read better written out.
    if (a >= 1e4 && a < 1e15 && v == std::round(v))
        std::snprintf(buf, sizeof buf, "%.0f", v);
    else
        std::snprintf(buf, sizeof buf, "%.4g", v);
    return buf;
}

std::array<uint8_t, 3> plotSeriesColour(size_t i) { return kPalette[i % kPaletteSize]; }

util::Rgba8Image renderPlot(const PlotSpec& spec, uint32_t width, uint32_t height) {
    const Layout L = computeLayout(spec, width, height);
    const PlotAxis &ax = L.frame.x, &ay = L.frame.y;
    const int s = L.scale;
    util::Rgba8Image img{width, height, std::vector<uint8_t>(size_t(width) * height * 4)};
    fillRect(img, 0, 0, int(width), int(height), kBackground);

    // Grid and ticks with labels: x labels centred under their tick (kept inside the image),
    // y labels right-aligned and vertically centred on theirs.
    for (double t : ax.ticks) {
        const int x = px(ax.toPixel(t));
        drawLine(img, x, L.plotT, x, L.plotB, 1, kGrid);
        drawLine(img, x, L.plotB, x, L.plotB + L.tickLen, 1, kAxis);
        const std::string label = formatTick(t);
        const int w = textWidth(label, s);
        text(img, std::clamp(x - w / 2, 0, int(width) - w), L.plotB + L.tickLen + L.gap, label, s, kText);
    }
    for (double t : ay.ticks) {
        const int y = px(ay.toPixel(t));
        drawLine(img, L.plotL, y, L.plotR, y, 1, kGrid);
        drawLine(img, L.plotL - L.tickLen, y, L.plotL, y, 1, kAxis);
        const std::string label = formatTick(t);
        text(img, L.plotL - L.tickLen - L.gap - textWidth(label, s), y - L.capH / 2, label, s, kText);
    }
    // Frame over the grid's end points.
    drawLine(img, L.plotL, L.plotT, L.plotR, L.plotT, 1, kAxis);
    drawLine(img, L.plotL, L.plotB, L.plotR, L.plotB, 1, kAxis);
    drawLine(img, L.plotL, L.plotT, L.plotL, L.plotB, 1, kAxis);
    drawLine(img, L.plotR, L.plotT, L.plotR, L.plotB, 1, kAxis);

    // Axis labels centred on the plot area; the y label reads bottom to top at the left edge.
    if (!spec.xLabel.empty())
        text(img, (L.plotL + L.plotR - textWidth(spec.xLabel, s)) / 2, int(height) - L.pad - L.lineH, spec.xLabel,
             s, kText);
    if (!spec.yLabel.empty())
        textUp(img, L.pad, std::max(0, (L.plotT + L.plotB - textWidth(spec.yLabel, s)) / 2), spec.yLabel, s, kText);

    // Series: all lines first, then all markers, so no line hides a point.
    for (size_t i = 0; i < spec.series.size(); ++i) {
        const PlotSeries& ser = spec.series[i];
        for (size_t k = 0; k + 1 < ser.x.size(); ++k)
            drawLine(img, px(ax.toPixel(ser.x[k])), px(ay.toPixel(ser.y[k])), px(ax.toPixel(ser.x[k + 1])),
                     px(ay.toPixel(ser.y[k + 1])), 2, plotSeriesColour(i));
    }
    for (size_t i = 0; i < spec.series.size(); ++i) {
        const PlotSeries& ser = spec.series[i];
        for (size_t k = 0; k < ser.x.size(); ++k)
            drawHaloMarker(img, px(ax.toPixel(ser.x[k])), px(ay.toPixel(ser.y[k])), L.markerR, i,
                           plotSeriesColour(i));
    }

    // Legend entries: a line segment with the series' marker, then its name.
    for (size_t i = 0; i < spec.series.size(); ++i) {
        const auto [x, y] = L.legendPos[i];
        const int midY = y + L.capH / 2;
        drawLine(img, x, midY, x + L.swatchW - 1, midY, 2, plotSeriesColour(i));
        drawHaloMarker(img, x + L.swatchW / 2, midY, L.markerR, i, plotSeriesColour(i));
        text(img, x + L.swatchW + L.gap, y, spec.series[i].name, s, kText);
    }

    // Title centred on the image, emboldened by drawing it twice one pixel apart.
    if (!spec.title.empty()) {
        const int x = std::max(L.pad, (int(width) - textWidth(spec.title, s)) / 2);
        text(img, x, L.titleY, spec.title, s, kText);
        text(img, x + 1, L.titleY, spec.title, s, kText);
    }
    return img;
}

util::Rgba8Image sideBySide(const std::vector<util::Rgba8Image>& charts) {
    if (charts.empty()) throw std::invalid_argument("sideBySide: no charts");
    util::Rgba8Image out{0, charts.front().height, {}};
    for (const util::Rgba8Image& c : charts) {
        if (c.height != out.height)
            throw std::invalid_argument("sideBySide: chart heights differ (" + std::to_string(c.height) + " vs " +
                                        std::to_string(out.height) + ")");
        if (c.pixels.size() != size_t(c.width) * c.height * 4)
            throw std::invalid_argument("sideBySide: a chart's pixels do not match its size");
        out.width += c.width;
    }
    out.pixels.resize(size_t(out.width) * out.height * 4);
    uint32_t x0 = 0;
    for (const util::Rgba8Image& c : charts) {
        if (c.width == 0) continue;
        for (uint32_t y = 0; y < c.height; ++y)
            std::copy_n(&c.pixels[size_t(y) * c.width * 4], size_t(c.width) * 4,
                        &out.pixels[(size_t(y) * out.width + x0) * 4]);
        x0 += c.width;
    }
    return out;
}

}  // namespace ppr::app
