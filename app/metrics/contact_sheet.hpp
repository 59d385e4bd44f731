#pragma once
// Contact sheets for `ppr compare`: labelled tiles in a grid, text drawn with stb_easy_font.
#include "util/image_io.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace ppr::app {

struct ContactTile {
    std::string label;
    util::Rgba8Image image;
};

// Layout (all in pixels). With n tiles, cols = min(columns, n), rows = ceil(n / cols), and the cell
// the size of the largest tile (cellW x cellH):
//   width  = cols * cellW + (cols + 1) * kSheetGap
//   height = rows * (kLabelStripHeight + cellH) + (rows + 1) * kSheetGap
// Cell (c, r) starts at (kSheetGap + c * (cellW + kSheetGap), kSheetGap + r * (kLabelStripHeight +
// cellH + kSheetGap)): first the label strip, then the tile, centred in the cell (offsets rounded down).
constexpr uint32_t kSheetGap = 4;
constexpr uint32_t kLabelStripHeight = 24;  // 2x stb_easy_font glyphs (18 px) + 3 px above and below
constexpr int kLabelScale = 2;
constexpr uint8_t kSheetBackground = 12;   // gaps and unused cell area
constexpr uint8_t kLabelBackground = 24;   // near-black label strip
constexpr uint8_t kLabelForeground = 210;  // light grey text

// Lays out tiles in a grid of `columns` columns (rows as needed), each cell the size of the largest
// tile, with a kSheetGap dark gap and a label strip above each tile (text clipped to the strip). An
// empty label draws no text but the strip stays. The sheet is opaque (alpha 255 everywhere; tile
// alpha is dropped). Throws std::invalid_argument for no tiles, columns == 0, or a tile whose
// pixels do not match its size.
util::Rgba8Image makeContactSheet(const std::vector<ContactTile>& tiles, uint32_t columns);

// Draws `text` into `image` with its top-left at (x, y), glyphs scaled by `scale` (< 1 counts as 1),
// in colour (r, g, b), alpha 255. Clipped to the image. '\n' starts a new line 12 * scale below;
// characters stb_easy_font has no glyph for are drawn as '?'.
void drawText(util::Rgba8Image& image, int x, int y, const std::string& text, int scale, uint8_t r, uint8_t g, uint8_t b);

// Width in pixels of the widest line drawText would draw for `text` at `scale` (< 1 counts as 1),
// including the 1-pixel spacing after the last glyph. Digits and capitals are 7 * scale pixels tall
// from the top of the line; descenders reach 9 * scale.
int textWidth(const std::string& text, int scale);

}  // namespace ppr::app
