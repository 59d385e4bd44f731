#include "metrics/contact_sheet.hpp"

// stb_easy_font is header-only with static functions; this is its only includer.
#include <stb_easy_font.h>

#include <algorithm>
#include <stdexcept>

namespace ppr::app {

namespace {

struct ClipRect {
    int x0, y0, x1, y1;  // half-open
};

void fillRect(util::Rgba8Image& img, ClipRect r, ClipRect clip, uint8_t cr, uint8_t cg, uint8_t cb) {
    r = {std::max(r.x0, clip.x0), std::max(r.y0, clip.y0), std::min(r.x1, clip.x1), std::min(r.y1, clip.y1)};
    for (int y = r.y0; y < r.y1; ++y)
        for (int x = r.x0; x < r.x1; ++x) {
            uint8_t* p = &img.pixels[(size_t(y) * img.width + x) * 4];
            p[0] = cr, p[1] = cg, p[2] = cb, p[3] = 255;
        }
}

// drawText with an extra clip rectangle (already inside the image), so a long label stays in its strip.
void drawTextClipped(util::Rgba8Image& image, int x, int y, const std::string& text, int scale, uint8_t r,
                     uint8_t g, uint8_t b, ClipRect clip) {
    if (text.empty()) return;
    scale = std::max(scale, 1);
    // stb_easy_font indexes its glyph table with (c - 32) unchecked: keep to printable ASCII and '\n'.
    std::string safe = text;
    for (char& c : safe)
        if (c != '\n' && (c < 32 || c > 126)) c = '?';
    // ~270 bytes per character on average (stb_easy_font.h); 1 KiB each is plenty for any glyph.
    std::vector<char> quads(safe.size() * 1024);
    const int n = stb_easy_font_print(0.0f, 0.0f, safe.data(), nullptr, quads.data(), static_cast<int>(quads.size()));
    // Each quad is 4 vertices of 16 bytes (x, y, z floats + colour); corners 0 and 2 are opposite.
    // Coordinates are whole font pixels, so each quad is an exact rectangle of scale x scale cells.
    for (int q = 0; q < n; ++q) {
        const float* v0 = reinterpret_cast<const float*>(quads.data() + q * 64);
        const float* v2 = reinterpret_cast<const float*>(quads.data() + q * 64 + 32);
        const ClipRect rect{x + static_cast<int>(v0[0]) * scale, y + static_cast<int>(v0[1]) * scale,
                            x + static_cast<int>(v2[0]) * scale, y + static_cast<int>(v2[1]) * scale};
        fillRect(image, rect, clip, r, g, b);
    }
}

void checkTile(const ContactTile& t) {
    if (t.image.pixels.size() != size_t(t.image.width) * t.image.height * 4)
        throw std::invalid_argument("contact sheet tile '" + t.label + "': pixels do not match its " +
                                    std::to_string(t.image.width) + "x" + std::to_string(t.image.height) + " size");
}

}  // namespace

void drawText(util::Rgba8Image& image, int x, int y, const std::string& text, int scale, uint8_t r, uint8_t g,
              uint8_t b) {
    if (image.pixels.size() != size_t(image.width) * image.height * 4) return;  // nothing valid to draw into
    drawTextClipped(image, x, y, text, scale, r, g, b,
                    ClipRect{0, 0, static_cast<int>(image.width), static_cast<int>(image.height)});
}

int textWidth(const std::string& text, int scale) {
    // Same substitution as drawTextClipped, so the width matches what is drawn.
    std::string safe = text;
    for (char& c : safe)
        if (c != '\n' && (c < 32 || c > 126)) c = '?';
    return stb_easy_font_width(safe.data()) * std::max(scale, 1);
}

util::Rgba8Image makeContactSheet(const std::vector<ContactTile>& tiles, uint32_t columns) {
    if (tiles.empty()) throw std::invalid_argument("contact sheet: no tiles");
    if (columns == 0) throw std::invalid_argument("contact sheet: columns must be at least 1");
    uint32_t cellW = 0, cellH = 0;
    for (const ContactTile& t : tiles) {
        checkTile(t);
        cellW = std::max(cellW, t.image.width);
        cellH = std::max(cellH, t.image.height);
    }
    const uint32_t n = static_cast<uint32_t>(tiles.size());
    const uint32_t cols = std::min(columns, n);
    const uint32_t rows = (n + cols - 1) / cols;
    const uint32_t pitchX = cellW + kSheetGap, pitchY = kLabelStripHeight + cellH + kSheetGap;

    util::Rgba8Image sheet;
    sheet.width = cols * cellW + (cols + 1) * kSheetGap;
    sheet.height = rows * (kLabelStripHeight + cellH) + (rows + 1) * kSheetGap;
    sheet.pixels.resize(size_t(sheet.width) * sheet.height * 4);
    const ClipRect all{0, 0, static_cast<int>(sheet.width), static_cast<int>(sheet.height)};
    fillRect(sheet, all, all, kSheetBackground, kSheetBackground, kSheetBackground);

    for (uint32_t i = 0; i < n; ++i) {
        const ContactTile& t = tiles[i];
        const int cx = static_cast<int>(kSheetGap + (i % cols) * pitchX);
        const int cy = static_cast<int>(kSheetGap + (i / cols) * pitchY);
        const ClipRect strip{cx, cy, cx + static_cast<int>(cellW), cy + static_cast<int>(kLabelStripHeight)};
        fillRect(sheet, strip, all, kLabelBackground, kLabelBackground, kLabelBackground);
        drawTextClipped(sheet, cx + 4, cy + 3, t.label, kLabelScale, kLabelForeground, kLabelForeground,
                        kLabelForeground, strip);

        const uint32_t ox = cx + (cellW - t.image.width) / 2;
        const uint32_t oy = cy + kLabelStripHeight + (cellH - t.image.height) / 2;
        for (uint32_t y = 0; y < t.image.height; ++y)
            for (uint32_t x = 0; x < t.image.width; ++x) {
                const uint8_t* src = &t.image.pixels[(size_t(y) * t.image.width + x) * 4];
                uint8_t* dst = &sheet.pixels[(size_t(oy + y) * sheet.width + ox + x) * 4];
                dst[0] = src[0], dst[1] = src[1], dst[2] = src[2], dst[3] = 255;  // opaque sheet
            }
    }
    return sheet;
}

}  // namespace ppr::app
