#pragma once
// Glass-panel atlas layout: each frame every visible glass panel gets a region of a square r32ui
// atlas sized to its on-screen footprint, so PPR writes the panel's reflection data there instead of
// into a screen-sized buffer. Pure CPU math; the GPU passes only consume the resulting rectangles.
#include "scene/reflector.hpp"

#include <glm/glm.hpp>

#include <cstdint>
#include <optional>
#include <vector>

namespace ppr::scene {

// Pixels, half-open [x0, x1) × [y0, y1), y down (row 0 = top, as in camera.hpp).
struct ScreenRect {
    int32_t x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    bool empty() const { return x1 <= x0 || y1 <= y0; }
    int32_t width() const { return x1 > x0 ? x1 - x0 : 0; }
    int32_t height() const { return y1 > y0 ? y1 - y0 : 0; }
    bool operator==(const ScreenRect&) const = default;
};

// The panel rectangle's on-screen bounds: its quad clipped against the near plane in clip space
// (w >= near·(1 + eps), Sutherland–Hodgman), projected, bounding box rounded outwards, clipped to the
// screen. Empty when nothing is on screen or the camera sees the panel from behind
// (dot(normal, eye − center) <= 0). `viewProj` = projectionMatrix(...) · viewMatrix(...).
ScreenRect glassScreenRect(const Reflector& panel, const glm::mat4& viewProj, const glm::vec3& eye, float nearPlane,
                           glm::uvec2 screen);

// Eye → nearest point of the panel rectangle (metres).
float glassPanelDistance(const Reflector& panel, const glm::vec3& eye);

constexpr float kMinGlassScale = 1.0f / 8.0f;  // below this a panel is dropped rather than shrunk further
constexpr int32_t kGlassAtlasGutter = 1;       // texels between regions: bilinear taps never reach a neighbour

// Shelf packer: places `sizes` (each ≥ 1×1) in an atlasSize² square, `gutter` texels apart, in order of
// height (descending, ties by position in `sizes`), each into the first shelf with room. Returns the
// top-left origin of each size (same order as `sizes`), or nullopt when they do not all fit.
std::optional<std::vector<glm::ivec2>> packRects(const std::vector<glm::ivec2>& sizes, uint32_t atlasSize,
                                                 int32_t gutter = kGlassAtlasGutter);

struct GlassRegion {
    uint32_t reflectorIndex = 0;  // into the scene's reflector list
    ScreenRect screen;            // the footprint on screen
    glm::ivec2 atlasOrigin{0};    // top-left texel in the atlas
    glm::ivec2 atlasSize{0};      // texels; = ceil(screen size × scale), at least 1×1
    float scale = 1.0f;           // atlas texels per screen pixel (1 = full resolution, < 1 = scaled down)
    float distance = 0.0f;        // eye → nearest point of the panel rectangle (for ordering / dropping)
    bool operator==(const GlassRegion&) const = default;
};

struct GlassAtlasLayout {
    std::vector<GlassRegion> regions;  // the panels that got a region, by ascending reflectorIndex
    uint32_t visible = 0;              // panels with a non-empty footprint
    uint32_t scaled = 0;               // of those, how many got scale < 1
    uint32_t dropped = 0;              // visible panels that got no region (atlas overflow)
    float scale = 1.0f;                // the common scale applied (1 when everything fit)
};

// Packs the visible panels' footprints into the atlas (packRects). Overflow policy, predictable and
// visible: all regions shrink by one common factor s, the largest in [kMinGlassScale, 1] that fits
// (bisection); if even kMinGlassScale does not fit, the farthest panels (by distance, ties: higher
// reflectorIndex first) are dropped one by one at that scale until the rest fit. Duplicate and
// out-of-range indices in `glassIndices` are ignored; the result does not depend on their order.
GlassAtlasLayout packGlassAtlas(const std::vector<Reflector>& reflectors, const std::vector<uint32_t>& glassIndices,
                                const glm::mat4& viewProj, const glm::vec3& eye, float nearPlane, glm::uvec2 screen,
                                uint32_t atlasSize);

// The atlas texels the glass passes define, as half-open texel rectangles clipped to the atlas: each
// region grown by a one-texel ring (it lies in the gutter: kGlassAtlasGutter ≥ 1), which is all the
// glass pass's bilinear taps read. PPR's resolve writes exactly these and leaves the rest of its
// reflection atlas as it finds it (glass_reflect.comp); a readback keeps only these.
std::vector<ScreenRect> glassAtlasDefinedRects(const std::vector<GlassRegion>& regions, uint32_t atlasSize);

// Screen pixel ↔ atlas texel coordinates of a region: atlasOrigin + (p − screen.x0y0) · scale, and back.
glm::vec2 atlasFromScreen(const GlassRegion& region, glm::vec2 screenPixel);
glm::vec2 screenFromAtlas(const GlassRegion& region, glm::vec2 atlasTexel);

}  // namespace ppr::scene
