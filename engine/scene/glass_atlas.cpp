// Glass-panel atlas layout: screen footprints, a deterministic shelf packer and the overflow policy
// (uniform shrink, then drop the farthest panels).
#include "scene/glass_atlas.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace ppr::scene {

namespace {

// Clip slightly in front of the near plane so the projected x/w, y/w stay finite and well conditioned.
constexpr float kNearEps = 1e-4f;
// Projected corners within this many pixels of a pixel edge snap to it, so float noise in an exact
// footprint does not grow the rectangle by a whole pixel.
constexpr float kSnapPixels = 1e-3f;
constexpr int kBisectionSteps = 10;  // (1 − 1/8) / 2^10 ≈ 0.001 scale resolution

glm::ivec2 scaledSize(const ScreenRect& r, float s) {
    // double: w·s must not round up past an integer when it is exact (e.g. s = 1).
    return {std::max(1, static_cast<int>(std::ceil(static_cast<double>(r.width()) * s))),
            std::max(1, static_cast<int>(std::ceil(static_cast<double>(r.height()) * s)))};
}

}  // namespace

ScreenRect glassScreenRect(const Reflector& panel, const glm::mat4& viewProj, const glm::vec3& eye, float nearPlane,
                           glm::uvec2 screen) {
    if (screen.x == 0 || screen.y == 0) return {};
    if (glm::dot(panel.normal, eye - panel.center) <= 0.0f) return {};  // seen from behind (or edge-on)

    const glm::vec3 u = panel.tangent * panel.halfExtents.x, v = panel.bitangent() * panel.halfExtents.y;
    const glm::vec3 corners[4] = {panel.center - u - v, panel.center + u - v, panel.center + u + v,
                                  panel.center - u + v};
    glm::vec4 clip[4];
    for (int i = 0; i < 4; ++i) clip[i] = viewProj * glm::vec4(corners[i], 1.0f);

    // Sutherland–Hodgman against the single plane w >= wMin: a quad gains at most one vertex.
    const float wMin = nearPlane * (1.0f + kNearEps);
    glm::vec4 poly[5];
    int n = 0;
    for (int i = 0; i < 4; ++i) {
        const glm::vec4& a = clip[i];
        const glm::vec4& b = clip[(i + 1) % 4];
        const bool inA = a.w >= wMin, inB = b.w >= wMin;
        if (inA) poly[n++] = a;
        if (inA != inB) poly[n++] = a + (b - a) * ((wMin - a.w) / (b.w - a.w));
    }
    if (n == 0) return {};

    const glm::vec2 size(screen);
    glm::vec2 lo(std::numeric_limits<float>::max()), hi(std::numeric_limits<float>::lowest());
    for (int i = 0; i < n; ++i) {
        const glm::vec2 pixel = (glm::vec2(poly[i]) / poly[i].w * 0.5f + 0.5f) * size;
        if (!std::isfinite(pixel.x) || !std::isfinite(pixel.y)) return {};
        lo = glm::min(lo, pixel);
        hi = glm::max(hi, pixel);
    }
    // Clamp in float before converting: near the near plane the projection can be far off screen.
    lo = glm::clamp(lo, glm::vec2(0.0f), size);
    hi = glm::clamp(hi, glm::vec2(0.0f), size);
    ScreenRect r;
    r.x0 = static_cast<int32_t>(std::floor(lo.x + kSnapPixels));
    r.y0 = static_cast<int32_t>(std::floor(lo.y + kSnapPixels));
    r.x1 = static_cast<int32_t>(std::ceil(hi.x - kSnapPixels));
    r.y1 = static_cast<int32_t>(std::ceil(hi.y - kSnapPixels));
    return r.empty() ? ScreenRect{} : r;
}

float glassPanelDistance(const Reflector& panel, const glm::vec3& eye) {
    const glm::vec3 d = eye - panel.center, t = panel.tangent, b = panel.bitangent();
    const float a = std::clamp(glm::dot(d, t), -panel.halfExtents.x, panel.halfExtents.x);
    const float c = std::clamp(glm::dot(d, b), -panel.halfExtents.y, panel.halfExtents.y);
    return glm::length(eye - (panel.center + a * t + c * b));
}

std::optional<std::vector<glm::ivec2>> packRects(const std::vector<glm::ivec2>& sizes, uint32_t atlasSize,
                                                 int32_t gutter) {
    const int64_t atlas = std::min<int64_t>(atlasSize, std::numeric_limits<int32_t>::max());
    const int64_t g = std::max<int32_t>(gutter, 0);
    std::vector<size_t> order(sizes.size());
    std::iota(order.begin(), order.end(), size_t{0});
    // Tallest first: every later rect fits any earlier shelf's height, so first fit only checks width.
    std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return sizes[a].y > sizes[b].y; });

    struct Shelf {
        int64_t y, height, nextX;
    };
    std::vector<Shelf> shelves;
    std::vector<glm::ivec2> origins(sizes.size());
    for (size_t i : order) {
        const int64_t w = sizes[i].x, h = sizes[i].y;
        if (w < 1 || h < 1 || w > atlas || h > atlas) return std::nullopt;
        bool placed = false;
        for (Shelf& s : shelves) {
            if (s.nextX + w <= atlas) {
                origins[i] = {static_cast<int32_t>(s.nextX), static_cast<int32_t>(s.y)};
                s.nextX += w + g;
                placed = true;
                break;
            }
        }
        if (placed) continue;
        const int64_t y = shelves.empty() ? 0 : shelves.back().y + shelves.back().height + g;
        if (y + h > atlas) return std::nullopt;
        shelves.push_back({y, h, w + g});
        origins[i] = {0, static_cast<int32_t>(y)};
    }
    return origins;
}

std::vector<ScreenRect> glassAtlasDefinedRects(const std::vector<GlassRegion>& regions, uint32_t atlasSize) {
    static_assert(kGlassAtlasGutter >= 1, "the rings must not reach into a neighbouring region");
    const int32_t size = static_cast<int32_t>(std::min<uint32_t>(atlasSize, std::numeric_limits<int32_t>::max()));
    std::vector<ScreenRect> rects;
    for (const GlassRegion& r : regions) {
        const ScreenRect ring{std::max(r.atlasOrigin.x - 1, 0), std::max(r.atlasOrigin.y - 1, 0),
                              std::min(r.atlasOrigin.x + r.atlasSize.x + 1, size), std::min(r.atlasOrigin.y + r.atlasSize.y + 1, size)};
        if (!ring.empty()) rects.push_back(ring);
    }
    return rects;
}

GlassAtlasLayout packGlassAtlas(const std::vector<Reflector>& reflectors, const std::vector<uint32_t>& glassIndices,
                                const glm::mat4& viewProj, const glm::vec3& eye, float nearPlane, glm::uvec2 screen,
                                uint32_t atlasSize) {
    // Sorted, unique indices: the layout is independent of the caller's order and ties break by index.
    std::vector<uint32_t> indices = glassIndices;
    std::sort(indices.begin(), indices.end());
    indices.erase(std::unique(indices.begin(), indices.end()), indices.end());

    GlassAtlasLayout layout;
    std::vector<GlassRegion> candidates;
    for (uint32_t index : indices) {
        if (index >= reflectors.size()) continue;
        const Reflector& panel = reflectors[index];
        GlassRegion r;
        r.reflectorIndex = index;
        r.screen = glassScreenRect(panel, viewProj, eye, nearPlane, screen);
        if (r.screen.empty()) continue;
        r.distance = glassPanelDistance(panel, eye);
        candidates.push_back(r);
    }
    layout.visible = static_cast<uint32_t>(candidates.size());

    // Packs `regions` at scale s into the layout; false (layout untouched) when they do not fit.
    auto tryPack = [&](const std::vector<GlassRegion>& regions, float s) {
        std::vector<glm::ivec2> sizes;
        sizes.reserve(regions.size());
        for (const GlassRegion& r : regions) sizes.push_back(scaledSize(r.screen, s));
        const auto origins = packRects(sizes, atlasSize);
        if (!origins) return false;
        layout.regions = regions;
        for (size_t i = 0; i < regions.size(); ++i) {
            layout.regions[i].atlasOrigin = (*origins)[i];
            layout.regions[i].atlasSize = sizes[i];
            layout.regions[i].scale = s;
        }
        layout.scale = s;
        layout.scaled = s < 1.0f ? static_cast<uint32_t>(regions.size()) : 0;
        layout.dropped = layout.visible - static_cast<uint32_t>(regions.size());
        return true;
    };

    if (candidates.empty() || tryPack(candidates, 1.0f)) return layout;
    if (tryPack(candidates, kMinGlassScale)) {
        // Largest fitting s: lo always fits, hi never did. Shelf packing is not strictly monotonic in s,
        // but the result is always a packing that was actually verified.
        float lo = kMinGlassScale, hi = 1.0f;
        for (int i = 0; i < kBisectionSteps; ++i) {
            const float mid = 0.5f * (lo + hi);
            (tryPack(candidates, mid) ? lo : hi) = mid;
        }
        tryPack(candidates, lo);  // redo at the final s (the last try may have been a failure)
        return layout;
    }

    // Even 1/8 overflows: drop the farthest panels one at a time (ties: higher index first).
    std::vector<GlassRegion> kept = candidates;
    do {
        kept.erase(std::max_element(kept.begin(), kept.end(), [](const GlassRegion& a, const GlassRegion& b) {
            return a.distance != b.distance ? a.distance < b.distance : a.reflectorIndex < b.reflectorIndex;
        }));
    } while (!tryPack(kept, kMinGlassScale));  // terminates: an empty set always fits
    return layout;
}

glm::vec2 atlasFromScreen(const GlassRegion& region, glm::vec2 screenPixel) {
    return glm::vec2(region.atlasOrigin) + (screenPixel - glm::vec2(region.screen.x0, region.screen.y0)) * region.scale;
}

glm::vec2 screenFromAtlas(const GlassRegion& region, glm::vec2 atlasTexel) {
    return glm::vec2(region.screen.x0, region.screen.y0) + (atlasTexel - glm::vec2(region.atlasOrigin)) / region.scale;
}

}  // namespace ppr::scene
