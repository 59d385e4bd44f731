// Contact sheet layout (sizes, tile offsets, centring, label strips) and text drawing.
#include "metrics/contact_sheet.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

using namespace ppr::app;
using ppr::util::Rgba8Image;

namespace {

Rgba8Image solid(uint32_t w, uint32_t h, uint8_t r, uint8_t g, uint8_t b) {
    Rgba8Image img{w, h, std::vector<uint8_t>(size_t(w) * h * 4, 128)};  // alpha 128: the sheet must drop it
    for (size_t i = 0; i < size_t(w) * h; ++i) img.pixels[i * 4] = r, img.pixels[i * 4 + 1] = g, img.pixels[i * 4 + 2] = b;
    return img;
}

const uint8_t* px(const Rgba8Image& img, uint32_t x, uint32_t y) {
    return &img.pixels[(size_t(y) * img.width + x) * 4];
}

void expectRgb(const Rgba8Image& img, uint32_t x, uint32_t y, uint8_t r, uint8_t g, uint8_t b) {
    const uint8_t* p = px(img, x, y);
    EXPECT_EQ(p[0], r) << "at " << x << "," << y;
    EXPECT_EQ(p[1], g) << "at " << x << "," << y;
    EXPECT_EQ(p[2], b) << "at " << x << "," << y;
    EXPECT_EQ(p[3], 255) << "at " << x << "," << y;
}

// Pixels in [x0,x1)x[y0,y1) that are not `background` grey.
int countNot(const Rgba8Image& img, uint32_t x0, uint32_t y0, uint32_t x1, uint32_t y1, uint8_t background) {
    int n = 0;
    for (uint32_t y = y0; y < y1; ++y)
        for (uint32_t x = x0; x < x1; ++x)
            if (px(img, x, y)[0] != background) ++n;
    return n;
}

}  // namespace

TEST(ContactSheet, DimensionsAndTileOffsets) {
    const std::vector<ContactTile> tiles = {
        {"ppr", solid(40, 30, 255, 0, 0)}, {"ssr", solid(40, 30, 0, 255, 0)}, {"planar", solid(40, 30, 0, 0, 255)}};
    const Rgba8Image sheet = makeContactSheet(tiles, 2);
    // 2 columns, 2 rows: 2*40 + 3*4 wide, 2*(24 + 30) + 3*4 high.
    ASSERT_EQ(sheet.width, 2u * 40u + 3u * kSheetGap);
    ASSERT_EQ(sheet.height, 2u * (kLabelStripHeight + 30u) + 3u * kSheetGap);
    EXPECT_EQ(sheet.width, 92u);
    EXPECT_EQ(sheet.height, 120u);
    ASSERT_EQ(sheet.pixels.size(), size_t(92) * 120 * 4);

    const uint32_t tileY0 = kSheetGap + kLabelStripHeight;                  // first row of tiles
    const uint32_t tileY1 = tileY0 + 30 + kSheetGap + kLabelStripHeight;    // second row
    const uint32_t tileX1 = kSheetGap + 40 + kSheetGap;                     // second column
    // Corners of each tile, opaque.
    expectRgb(sheet, kSheetGap, tileY0, 255, 0, 0);
    expectRgb(sheet, kSheetGap + 39, tileY0 + 29, 255, 0, 0);
    expectRgb(sheet, tileX1, tileY0, 0, 255, 0);
    expectRgb(sheet, tileX1 + 39, tileY0 + 29, 0, 255, 0);
    expectRgb(sheet, kSheetGap, tileY1, 0, 0, 255);
    expectRgb(sheet, kSheetGap + 39, tileY1 + 29, 0, 0, 255);
    // Gaps around them, and the unused fourth cell, are background.
    expectRgb(sheet, 0, 0, kSheetBackground, kSheetBackground, kSheetBackground);
    expectRgb(sheet, kSheetGap + 40, tileY0 + 10, kSheetBackground, kSheetBackground, kSheetBackground);
    expectRgb(sheet, kSheetGap + 10, tileY0 + 30, kSheetBackground, kSheetBackground, kSheetBackground);
    expectRgb(sheet, tileX1 + 20, tileY1 + 15, kSheetBackground, kSheetBackground, kSheetBackground);
    // The label strip sits right above each tile.
    expectRgb(sheet, kSheetGap + 39, tileY0 - 1, kLabelBackground, kLabelBackground, kLabelBackground);
}

TEST(ContactSheet, FewerTilesThanColumnsUsesOnlyTheNeededColumns) {
    const Rgba8Image sheet = makeContactSheet({{"a", solid(10, 10, 1, 2, 3)}}, 4);
    EXPECT_EQ(sheet.width, 10u + 2u * kSheetGap);
    EXPECT_EQ(sheet.height, kLabelStripHeight + 10u + 2u * kSheetGap);
}

TEST(ContactSheet, SmallerTilesAreCentred) {
    const Rgba8Image sheet = makeContactSheet({{"big", solid(40, 30, 200, 200, 200)}, {"small", solid(20, 10, 9, 99, 199)}}, 2);
    const uint32_t cellX = kSheetGap + 40 + kSheetGap, cellY = kSheetGap + kLabelStripHeight;
    expectRgb(sheet, cellX + 10, cellY + 10, 9, 99, 199);  // (40-20)/2, (30-10)/2
    expectRgb(sheet, cellX + 29, cellY + 19, 9, 99, 199);
    expectRgb(sheet, cellX + 9, cellY + 10, kSheetBackground, kSheetBackground, kSheetBackground);
    expectRgb(sheet, cellX + 30, cellY + 19, kSheetBackground, kSheetBackground, kSheetBackground);
    expectRgb(sheet, cellX + 10, cellY + 20, kSheetBackground, kSheetBackground, kSheetBackground);
}

TEST(ContactSheet, LabelsDrawInTheirStripOnly) {
    const Rgba8Image sheet = makeContactSheet(
        {{"ppr 41.2 dB", solid(60, 20, 0, 0, 0)},
         {"", solid(60, 20, 0, 0, 0)},
         {"a label far too long to fit in a sixty pixel strip", solid(60, 20, 0, 0, 0)}},
        3);
    const uint32_t strip = kSheetGap, pitch = 60 + kSheetGap;
    const int first = countNot(sheet, strip, kSheetGap, strip + 60, kSheetGap + kLabelStripHeight, kLabelBackground);
    EXPECT_GT(first, 20);
    EXPECT_EQ(countNot(sheet, strip, kSheetGap, strip + 60, kSheetGap + kLabelStripHeight, kLabelForeground) +
                  first,
              60 * int(kLabelStripHeight));  // every strip pixel is background or text colour
    // Empty label: the strip is there, plain.
    EXPECT_EQ(countNot(sheet, strip + pitch, kSheetGap, strip + pitch + 60, kSheetGap + kLabelStripHeight,
                       kLabelBackground),
              0);
    // Long label: clipped to its strip, so the gaps beside it stay background.
    EXPECT_GT(countNot(sheet, strip + 2 * pitch, kSheetGap, strip + 2 * pitch + 60, kSheetGap + kLabelStripHeight,
                       kLabelBackground),
              0);
    EXPECT_EQ(countNot(sheet, sheet.width - kSheetGap, 0, sheet.width, sheet.height, kSheetBackground), 0);
    EXPECT_EQ(countNot(sheet, 0, 0, sheet.width, kSheetGap, kSheetBackground), 0);
}

TEST(ContactSheet, RejectsBadInput) {
    EXPECT_THROW(makeContactSheet({}, 2), std::invalid_argument);
    EXPECT_THROW(makeContactSheet({{"a", solid(4, 4, 0, 0, 0)}}, 0), std::invalid_argument);
    Rgba8Image broken = solid(4, 4, 0, 0, 0);
    broken.pixels.resize(10);
    EXPECT_THROW(makeContactSheet({{"a", broken}}, 1), std::invalid_argument);
}

TEST(DrawText, DrawsInTheGivenColour) {
    Rgba8Image img = solid(64, 32, 0, 0, 0);
    drawText(img, 2, 2, "Hi", 2, 10, 250, 30);
    int lit = 0;
    for (uint32_t y = 0; y < 32; ++y)
        for (uint32_t x = 0; x < 64; ++x)
            if (px(img, x, y)[1] == 250) {
                ++lit;
                EXPECT_EQ(px(img, x, y)[0], 10);
                EXPECT_EQ(px(img, x, y)[2], 30);
                EXPECT_GE(x, 2u);
                EXPECT_GE(y, 2u);
                EXPECT_LT(y, 2u + 2u * 9u);  // glyphs are 9 font pixels tall at most
            }
    EXPECT_GT(lit, 0);
    // Scale 2 draws whole 2x2 blocks: lit pixel count is a multiple of 4.
    EXPECT_EQ(lit % 4, 0);
}

TEST(DrawText, ClipsAtAndBeyondTheEdges) {
    Rgba8Image img = solid(16, 16, 0, 0, 0);
    drawText(img, -5, -5, "WWWW", 3, 255, 255, 255);  // partly visible
    EXPECT_GT(countNot(img, 0, 0, 16, 16, 0), 0);
    Rgba8Image untouched = solid(16, 16, 0, 0, 0);
    drawText(untouched, -1000, 3, "far left", 2, 255, 255, 255);
    drawText(untouched, 1000, 1000, "far away", 2, 255, 255, 255);
    drawText(untouched, 3, -100, "above", 2, 255, 255, 255);
    drawText(untouched, 3, 16, "just below", 1, 255, 255, 255);
    EXPECT_EQ(countNot(untouched, 0, 0, 16, 16, 0), 0);
    // Control and non-ASCII bytes neither crash nor index outside the font.
    drawText(img, 0, 0, std::string("\t\x01\xff\xc3\xa9\n\x7f"), 1, 255, 255, 255);
    Rgba8Image empty;
    drawText(empty, 0, 0, "x", 1, 255, 255, 255);
}
