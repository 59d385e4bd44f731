// Glass-panel atlas layout (engine/scene/glass_atlas.hpp): screen footprints, the shelf packer and
// the overflow policy (uniform shrink, then drop the farthest panels).
#include "scene/camera.hpp"
#include "scene/glass_atlas.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

using namespace ppr::scene;

namespace {

Reflector glassPanel(glm::vec3 center, glm::vec3 normal, glm::vec3 tangent, glm::vec2 halfExtents) {
    Reflector r;
    r.center = center;
    r.normal = normal;
    r.tangent = tangent;
    r.halfExtents = halfExtents;
    r.kind = ReflectorKind::Glass;
    return r;
}

// A panel facing +Z (towards a camera at the origin looking down −Z), tangent +X, bitangent +Y.
Reflector facingPanel(glm::vec3 center, glm::vec2 halfExtents) {
    return glassPanel(center, {0, 0, 1}, {1, 0, 0}, halfExtents);
}

struct View {
    glm::mat4 viewProj;
    glm::vec3 eye;
    glm::uvec2 screen;
};

View makeView(const CameraPose& pose, glm::uvec2 screen) {
    const float aspect = float(screen.x) / float(screen.y);
    return {projectionMatrix(pose.fovYDeg, aspect, kNearPlane) * viewMatrix(pose), pose.position, screen};
}

ScreenRect rectOf(const Reflector& panel, const View& v) {
    return glassScreenRect(panel, v.viewProj, v.eye, kNearPlane, v.screen);
}

GlassAtlasLayout pack(const std::vector<Reflector>& panels, const std::vector<uint32_t>& indices, const View& v,
                      uint32_t atlasSize) {
    return packGlassAtlas(panels, indices, v.viewProj, v.eye, kNearPlane, v.screen, atlasSize);
}

std::vector<uint32_t> allIndices(size_t n) {
    std::vector<uint32_t> idx(n);
    for (size_t i = 0; i < n; ++i) idx[i] = uint32_t(i);
    return idx;
}

// Rectangles [o, o + s) pairwise at least `gutter` apart and inside [0, atlas)². Returns a failure message or "".
std::string checkPacking(const std::vector<glm::ivec2>& origins, const std::vector<glm::ivec2>& sizes, int atlas,
                         int gutter) {
    if (origins.size() != sizes.size()) return "size mismatch";
    for (size_t i = 0; i < sizes.size(); ++i) {
        const glm::ivec2 o = origins[i], e = origins[i] + sizes[i];
        if (o.x < 0 || o.y < 0 || e.x > atlas || e.y > atlas)
            return "rect " + std::to_string(i) + " leaves the atlas";
        for (size_t j = 0; j < i; ++j) {
            const glm::ivec2 p = origins[j], f = origins[j] + sizes[j];
            const bool apart = o.x >= f.x + gutter || p.x >= e.x + gutter || o.y >= f.y + gutter || p.y >= e.y + gutter;
            if (!apart) return "rects " + std::to_string(j) + " and " + std::to_string(i) + " overlap (gutter included)";
        }
    }
    return "";
}

glm::ivec2 expectedAtlasSize(const ScreenRect& r, float s) {
    return {std::max(1, int(std::ceil(double(r.width()) * s))), std::max(1, int(std::ceil(double(r.height()) * s)))};
}

// Every invariant a layout must hold, whatever the overflow case.
void expectValidLayout(const GlassAtlasLayout& layout, uint32_t atlasSize) {
    std::vector<glm::ivec2> origins, sizes;
    for (size_t i = 0; i < layout.regions.size(); ++i) {
        const GlassRegion& r = layout.regions[i];
        origins.push_back(r.atlasOrigin);
        sizes.push_back(r.atlasSize);
        EXPECT_FALSE(r.screen.empty());
        EXPECT_EQ(r.scale, layout.scale) << "one common scale";
        EXPECT_EQ(r.atlasSize, expectedAtlasSize(r.screen, r.scale));
        // The whole footprint maps inside its own region.
        const glm::vec2 end = atlasFromScreen(r, {r.screen.x1, r.screen.y1});
        EXPECT_LE(end.x, float(r.atlasOrigin.x + r.atlasSize.x) + 1e-3f);
        EXPECT_LE(end.y, float(r.atlasOrigin.y + r.atlasSize.y) + 1e-3f);
        if (i > 0) {
            EXPECT_LT(layout.regions[i - 1].reflectorIndex, r.reflectorIndex) << "sorted by index";
        }
    }
    EXPECT_EQ(checkPacking(origins, sizes, int(atlasSize), kGlassAtlasGutter), "");
    EXPECT_EQ(layout.regions.size() + layout.dropped, layout.visible);
    EXPECT_EQ(layout.scaled, layout.scale < 1.0f ? layout.regions.size() : 0u);
    EXPECT_GE(layout.scale, kMinGlassScale);
    EXPECT_LE(layout.scale, 1.0f);
}

bool sameLayout(const GlassAtlasLayout& a, const GlassAtlasLayout& b) {
    return a.regions == b.regions && a.visible == b.visible && a.scaled == b.scaled && a.dropped == b.dropped &&
           a.scale == b.scale;
}

}  // namespace

// ---------------------------------------------------------------- packRects

TEST(PackRects, RandomSetsNeverOverlapAndStayInside) {
    std::mt19937 rng(20240611u);
    const uint32_t atlases[] = {16, 64, 256, 1024};
    int packed = 0, singleShelf = 0;
    const int cases = 5000;
    for (int c = 0; c < cases; ++c) {
        const uint32_t atlas = atlases[c % 4];
        const int n = std::uniform_int_distribution<int>(1, 48)(rng);
        // Mix of scales: from many tiny rects to a few atlas-sized ones.
        const int maxSide = std::max(1, int(atlas) >> std::uniform_int_distribution<int>(0, 5)(rng));
        std::uniform_int_distribution<int> side(1, maxSide);
        std::vector<glm::ivec2> sizes(n);
        for (auto& s : sizes) s = {side(rng), side(rng)};
        const auto origins = packRects(sizes, atlas);
        if (origins) {
            ++packed;
            ASSERT_EQ(checkPacking(*origins, sizes, int(atlas), kGlassAtlasGutter), "") << "case " << c;
        }
        // A set that fits in one row must always pack.
        int rowWidth = -kGlassAtlasGutter, maxHeight = 0;
        for (auto& s : sizes) rowWidth += s.x + kGlassAtlasGutter, maxHeight = std::max(maxHeight, s.y);
        if (rowWidth <= int(atlas) && maxHeight <= int(atlas)) {
            ++singleShelf;
            EXPECT_TRUE(origins.has_value()) << "case " << c << ": one row of width " << rowWidth << " must fit";
        }
    }
    // The property is not vacuous: both outcomes happen often.
    EXPECT_GT(packed, cases / 5);
    EXPECT_LT(packed, cases);
    EXPECT_GT(singleShelf, 50);
}

TEST(PackRects, GridOfEqualSquaresFitsExactly) {
    // 9×9 squares with a 1-texel gutter: 10 per row and 10 rows in 100² (the last ends at 99).
    for (uint32_t atlas : {99u, 100u}) {
        std::vector<glm::ivec2> sizes(100, glm::ivec2(9, 9));
        const auto origins = packRects(sizes, atlas);
        ASSERT_TRUE(origins.has_value()) << atlas;
        EXPECT_EQ(checkPacking(*origins, sizes, int(atlas), 1), "");
        EXPECT_EQ((*origins)[0], glm::ivec2(0, 0));
        EXPECT_EQ((*origins)[1], glm::ivec2(10, 0));   // equal heights keep input order, left to right
        EXPECT_EQ((*origins)[10], glm::ivec2(0, 10));  // next shelf
        EXPECT_EQ((*origins)[99], glm::ivec2(90, 90));
        sizes.push_back({9, 9});
        EXPECT_FALSE(packRects(sizes, atlas).has_value()) << "the 101st square has no room";
    }
    EXPECT_FALSE(packRects(std::vector<glm::ivec2>(100, glm::ivec2(9, 9)), 98).has_value());
    // Without a gutter 10×10 squares tile 100² exactly.
    const std::vector<glm::ivec2> tiles(100, glm::ivec2(10, 10));
    const auto tiled = packRects(tiles, 100, 0);
    ASSERT_TRUE(tiled.has_value());
    EXPECT_EQ(checkPacking(*tiled, tiles, 100, 0), "");
}

TEST(PackRects, TallestFirstFirstFitAndEdgeCases) {
    // Heights sorted descending; a short rect goes into the first shelf with room.
    const std::vector<glm::ivec2> sizes = {{30, 10}, {60, 40}, {50, 20}, {30, 5}};
    const auto o = packRects(sizes, 100);
    ASSERT_TRUE(o.has_value());
    EXPECT_EQ((*o)[1], glm::ivec2(0, 0));    // tallest
    EXPECT_EQ((*o)[2], glm::ivec2(0, 41));   // does not fit beside it (61 + 50 > 100): new shelf
    EXPECT_EQ((*o)[0], glm::ivec2(61, 0));   // fits in the first shelf
    EXPECT_EQ((*o)[3], glm::ivec2(51, 41));  // first shelf full (92 + 30 > 100): second shelf

    EXPECT_TRUE(packRects({}, 16).has_value());
    EXPECT_TRUE(packRects({}, 16)->empty());
    EXPECT_TRUE(packRects({{16, 16}}, 16).has_value());
    EXPECT_FALSE(packRects({{17, 1}}, 16).has_value());
    EXPECT_FALSE(packRects({{1, 17}}, 16).has_value());
    EXPECT_FALSE(packRects({{0, 4}}, 16).has_value()) << "sizes must be at least 1x1";
    EXPECT_FALSE(packRects({{1, 1}}, 0).has_value());
}

// ---------------------------------------------------------------- glassScreenRect

TEST(GlassScreenRect, PanelStraightAheadMatchesHandProjection) {
    // fov 90° → f = 1; 800×600 → f/aspect = 0.75. Panel at z = −2 (w = 2), half extents 0.5 × 0.25:
    // x = ±0.5 → ndc ±0.1875 → pixel 400 ± 75 = [325, 475];
    // y = ±0.25 → ndc ∓0.125 (y flipped) → pixel 300 ∓ 37.5 = [262.5, 337.5] → rounded outwards [262, 338].
    const View v = makeView({{0, 0, 0}, 0, 0, 90}, {800, 600});
    EXPECT_EQ(rectOf(facingPanel({0, 0, -2}, {0.5f, 0.25f}), v), (ScreenRect{325, 262, 475, 338}));

    // Same numbers from a moved, turned camera: at (1,2,3) looking down +X (right = +Z), a panel 4 m
    // ahead facing −X with bitangent +Y, shifted 1 m right: z ∈ [0, 2] → ndc x ∈ [0, 0.375] → [400, 550];
    // y = ±0.5 at w = 4 → ndc ∓0.125 → [262.5, 337.5] → [262, 338].
    const View turned = makeView({{1, 2, 3}, 90, 0, 90}, {800, 600});
    const Reflector side = glassPanel({5, 2, 4}, {-1, 0, 0}, {0, 0, 1}, {1.0f, 0.5f});
    ASSERT_NEAR(glm::length(side.bitangent() - glm::vec3(0, 1, 0)), 0.0f, 1e-6f);
    EXPECT_EQ(rectOf(side, turned), (ScreenRect{400, 262, 550, 338}));
    EXPECT_NEAR(glassPanelDistance(side, turned.eye), 4.0f, 1e-5f);
}

TEST(GlassScreenRect, BehindCameraOrBackSideIsEmpty) {
    const View v = makeView({{0, 0, 0}, 0, 0, 90}, {800, 600});
    // Behind the camera, facing it: every corner has w < near.
    EXPECT_TRUE(rectOf(glassPanel({0, 0, 2}, {0, 0, -1}, {1, 0, 0}, {0.5f, 0.5f}), v).empty());
    // In front but seen from its back side.
    EXPECT_TRUE(rectOf(glassPanel({0, 0, -2}, {0, 0, -1}, {1, 0, 0}, {0.5f, 0.5f}), v).empty());
    EXPECT_FALSE(rectOf(glassPanel({0, 0, -2}, {0, 0, 1}, {1, 0, 0}, {0.5f, 0.5f}), v).empty());
    // Edge-on (eye in the plane).
    EXPECT_TRUE(rectOf(glassPanel({0, 0, -2}, {1, 0, 0}, {0, 0, 1}, {0.5f, 0.5f}), v).empty());
    // Entirely off screen, to the right; and a zero-sized screen.
    EXPECT_TRUE(rectOf(facingPanel({10, 0, -2}, {0.5f, 0.5f}), v).empty());
    EXPECT_TRUE(glassScreenRect(facingPanel({0, 0, -2}, {0.5f, 0.5f}), v.viewProj, v.eye, kNearPlane, {0, 600}).empty());
}

TEST(GlassScreenRect, PanelCrossingNearPlaneIsClipped) {
    // A floor 1 m below the eye from 10 m behind to 10 m ahead: the near part projects to infinity;
    // clipped at the near plane it covers the full width down to the bottom. The far edge (y = −1,
    // w = 10) sets the top: ndc y = f/10 with f = 1/tan(30°) → pixel (0.5 + f/20)·600 = 351.96 → 351.
    const View v = makeView({{0, 0, 0}, 0, 0, 60}, {800, 600});
    const Reflector floor = glassPanel({0, -1, 0}, {0, 1, 0}, {1, 0, 0}, {2.0f, 10.0f});
    const float f = 1.0f / std::tan(glm::radians(30.0f));
    const int top = int(std::floor((0.5f + f / 20.0f) * 600.0f));
    ASSERT_EQ(top, 351);
    EXPECT_EQ(rectOf(floor, v), (ScreenRect{0, top, 800, 600}));

    // A wall panel straddling the camera plane, seen at a grazing angle: finite and inside the screen.
    const Reflector wall = glassPanel({1, 0, 0}, {-1, 0, 0}, {0, 0, 1}, {3.0f, 1.0f});
    const ScreenRect r = rectOf(wall, v);
    ASSERT_FALSE(r.empty());
    EXPECT_GE(r.x0, 400);  // to the right of the view axis
    EXPECT_EQ(r.x1, 800);
    EXPECT_EQ(r.y0, 0);    // the near end fills the whole height
    EXPECT_EQ(r.y1, 600);
}

TEST(GlassScreenRect, PartlyOffScreenIsClippedToScreen) {
    // x ∈ [2, 3] at w = 2 → ndc [0.75, 1.125] → pixels [700, 850] → clipped to 800.
    const View v = makeView({{0, 0, 0}, 0, 0, 90}, {800, 600});
    EXPECT_EQ(rectOf(facingPanel({2.5f, 0, -2}, {0.5f, 0.25f}), v), (ScreenRect{700, 262, 800, 338}));
    // Larger than the view in every direction: the whole screen.
    EXPECT_EQ(rectOf(facingPanel({0, 0, -1}, {50, 50}), v), (ScreenRect{0, 0, 800, 600}));
}

TEST(GlassScreenRect, RandomPanelsAreConservativeAndInsideScreen) {
    std::mt19937 rng(7u);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    const glm::uvec2 screen{640, 360};
    int nonEmpty = 0;
    for (int c = 0; c < 2000; ++c) {
        const CameraPose pose{{u(rng) * 3, u(rng) * 3, u(rng) * 3}, u(rng) * 180, u(rng) * 60, 40 + 40 * (u(rng) + 1)};
        const View v = makeView(pose, screen);
        const glm::vec3 n = glm::normalize(glm::vec3(u(rng), u(rng), u(rng)) + glm::vec3(0, 0, 0.01f));
        const glm::vec3 t = glm::normalize(glm::cross(n, glm::normalize(glm::vec3(u(rng), u(rng), u(rng)) + 0.02f)));
        const Reflector p = glassPanel({u(rng) * 5, u(rng) * 5, u(rng) * 5}, n, t, {0.1f + (u(rng) + 1) * 2, 0.1f + (u(rng) + 1) * 2});
        const ScreenRect r = rectOf(p, v);
        if (r.empty()) continue;
        ++nonEmpty;
        ASSERT_GE(r.x0, 0);
        ASSERT_GE(r.y0, 0);
        ASSERT_LE(r.x1, int(screen.x));
        ASSERT_LE(r.y1, int(screen.y));
        // Every sampled point of the panel in front of the near plane and on screen lies in the rect.
        for (int i = 0; i <= 8; ++i)
            for (int j = 0; j <= 8; ++j) {
                const glm::vec3 q = p.center + p.tangent * p.halfExtents.x * (i / 4.0f - 1) +
                                    p.bitangent() * p.halfExtents.y * (j / 4.0f - 1);
                const glm::vec4 clip = v.viewProj * glm::vec4(q, 1);
                if (clip.w < kNearPlane * 1.01f) continue;
                const glm::vec2 px = (glm::vec2(clip) / clip.w * 0.5f + 0.5f) * glm::vec2(screen);
                if (px.x < 0 || px.y < 0 || px.x > screen.x || px.y > screen.y) continue;
                EXPECT_GE(px.x, r.x0 - 0.01f) << c;
                EXPECT_LE(px.x, r.x1 + 0.01f) << c;
                EXPECT_GE(px.y, r.y0 - 0.01f) << c;
                EXPECT_LE(px.y, r.y1 + 0.01f) << c;
            }
    }
    EXPECT_GT(nonEmpty, 100);
}

// ---------------------------------------------------------------- packGlassAtlas

TEST(GlassAtlas, EverythingFitsAtFullResolution) {
    const View v = makeView({{0, 0, 0}, 0, 0, 90}, {1920, 1080});
    std::vector<Reflector> scene = {
        facingPanel({-1, 0, -4}, {0.3f, 0.4f}),
        glassPanel({0, 0, -3}, {0, 0, -1}, {1, 0, 0}, {0.5f, 0.5f}),  // back side: not visible
        facingPanel({1, 0.5f, -5}, {0.5f, 0.2f}),
        facingPanel({0, 0, 3}, {0.5f, 0.5f}),                          // behind the camera
        facingPanel({0, -0.5f, -2}, {0.2f, 0.1f}),
    };
    scene[2].kind = ReflectorKind::Opaque;  // the caller decides which indices are glass
    const std::vector<uint32_t> glass = {4, 0, 1, 3, 2, 0, 99};  // unordered, a duplicate, out of range
    const GlassAtlasLayout layout = pack(scene, glass, v, 1024);
    expectValidLayout(layout, 1024);
    EXPECT_EQ(layout.visible, 3u);
    EXPECT_EQ(layout.dropped, 0u);
    EXPECT_EQ(layout.scaled, 0u);
    EXPECT_EQ(layout.scale, 1.0f);
    ASSERT_EQ(layout.regions.size(), 3u);
    const uint32_t expectedIndex[] = {0, 2, 4};
    for (size_t i = 0; i < 3; ++i) {
        const GlassRegion& r = layout.regions[i];
        EXPECT_EQ(r.reflectorIndex, expectedIndex[i]);
        EXPECT_EQ(r.screen, rectOf(scene[r.reflectorIndex], v));
        EXPECT_EQ(r.atlasSize, glm::ivec2(r.screen.width(), r.screen.height())) << "full resolution";
        EXPECT_NEAR(r.distance, glassPanelDistance(scene[r.reflectorIndex], v.eye), 1e-6f);
    }
    EXPECT_NEAR(layout.regions[2].distance, std::sqrt(2.0f * 2.0f + 0.4f * 0.4f), 1e-5f);  // nearest point at y = −0.4

    // Nothing visible: an empty layout at scale 1.
    const GlassAtlasLayout none = pack(scene, {1, 3}, v, 1024);
    EXPECT_TRUE(none.regions.empty());
    EXPECT_EQ(none.visible, 0u);
    EXPECT_EQ(none.scale, 1.0f);
}

TEST(GlassAtlas, OverflowScalesAllRegionsUniformly) {
    // A 4×3 wall of panels filling a 1920×1080 view, into a 512² atlas.
    const View v = makeView({{0, 0, 0}, 0, 0, 60}, {1920, 1080});
    std::vector<Reflector> scene;
    for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 4; ++i) scene.push_back(facingPanel({-1.5f + i, -1.0f + j, -2.0f - 0.3f * i}, {0.45f, 0.45f}));
    const uint32_t atlas = 512;
    const GlassAtlasLayout layout = pack(scene, allIndices(scene.size()), v, atlas);
    expectValidLayout(layout, atlas);
    EXPECT_EQ(layout.dropped, 0u);
    EXPECT_EQ(layout.visible, uint32_t(layout.regions.size()));
    EXPECT_GT(layout.visible, 6u);
    EXPECT_EQ(layout.scaled, layout.visible);
    EXPECT_LT(layout.scale, 1.0f);
    EXPECT_GT(layout.scale, kMinGlassScale);
    // The atlas is used, not shrunk needlessly: the regions cover a good part of it.
    int64_t area = 0;
    for (const GlassRegion& r : layout.regions) area += int64_t(r.atlasSize.x + 1) * (r.atlasSize.y + 1);
    EXPECT_GT(double(area), 0.4 * atlas * atlas);
}

TEST(GlassAtlas, BisectionFindsTheLargestScale) {
    // One panel covering the whole 1920×1080 screen into 512²: the width limits, s ≤ 512/1920.
    const View v = makeView({{0, 0, 0}, 0, 0, 60}, {1920, 1080});
    const std::vector<Reflector> scene = {facingPanel({0, 0, -1}, {20, 20})};
    const GlassAtlasLayout layout = pack(scene, {0}, v, 512);
    expectValidLayout(layout, 512);
    ASSERT_EQ(layout.regions.size(), 1u);
    EXPECT_EQ(layout.regions[0].screen, (ScreenRect{0, 0, 1920, 1080}));
    EXPECT_LE(layout.scale, 512.0f / 1920.0f);
    EXPECT_GT(layout.scale, 512.0f / 1920.0f - 0.002f);
    EXPECT_LE(layout.regions[0].atlasSize.x, 512);
    EXPECT_GE(layout.regions[0].atlasSize.x, 509);
}

TEST(GlassAtlas, ExtremeOverflowDropsFarthestFirst) {
    // 20 similar-sized panels at distances 2..11.5 m, their indices shuffled against distance; at
    // s = 1/8 each needs ~70×35 texels, so a 128² atlas holds only a few.
    const View v = makeView({{0, 0, 0}, 0, 0, 60}, {1920, 1080});
    std::vector<int> order(20);
    for (int i = 0; i < 20; ++i) order[i] = i;
    std::shuffle(order.begin(), order.end(), std::mt19937(99u));
    std::vector<Reflector> scene;
    for (int k : order) {
        const float d = 2.0f + 0.5f * k;
        scene.push_back(facingPanel({0.1f * d * (k % 5 - 2), 0, -d}, {0.3f * d, 0.15f * d}));
    }
    const uint32_t atlas = 128;
    const GlassAtlasLayout layout = pack(scene, allIndices(scene.size()), v, atlas);
    expectValidLayout(layout, atlas);
    EXPECT_EQ(layout.visible, 20u);
    EXPECT_EQ(layout.scale, kMinGlassScale);
    ASSERT_GT(layout.dropped, 0u);
    ASSERT_GT(layout.regions.size(), 0u);
    EXPECT_EQ(layout.scaled, uint32_t(layout.regions.size()));
    EXPECT_EQ(layout.regions.size() + layout.dropped, 20u);

    // The kept panels are exactly the nearest ones.
    std::vector<bool> kept(scene.size(), false);
    float farthestKept = 0.0f;
    for (const GlassRegion& r : layout.regions) kept[r.reflectorIndex] = true, farthestKept = std::max(farthestKept, r.distance);
    uint32_t nearestDropped = 0;
    float nearestDroppedDistance = 1e9f;
    for (uint32_t i = 0; i < scene.size(); ++i)
        if (!kept[i]) {
            const float d = glassPanelDistance(scene[i], v.eye);
            EXPECT_GT(d, farthestKept) << "panel " << i << " dropped while a farther one was kept";
            if (d < nearestDroppedDistance) nearestDroppedDistance = d, nearestDropped = i;
        }
    // Dropping stopped as soon as it fit: the kept set plus the nearest dropped panel does not fit.
    std::vector<glm::ivec2> sizes;
    for (uint32_t i = 0; i < scene.size(); ++i)
        if (kept[i] || i == nearestDropped) sizes.push_back(expectedAtlasSize(rectOf(scene[i], v), kMinGlassScale));
    EXPECT_FALSE(packRects(sizes, atlas).has_value());

    // An atlas too small for even one panel at 1/8 drops them all and says so.
    const GlassAtlasLayout tiny = pack(scene, allIndices(scene.size()), v, 8);
    expectValidLayout(tiny, 8);
    EXPECT_TRUE(tiny.regions.empty());
    EXPECT_EQ(tiny.dropped, 20u);
    EXPECT_EQ(tiny.scaled, 0u);
}

TEST(GlassAtlas, DeterministicAndIndependentOfInputOrder) {
    std::mt19937 rng(5u);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    const View v = makeView({{0, 1, 0}, 10, -5, 70}, {1280, 720});
    std::vector<Reflector> scene;
    for (int i = 0; i < 40; ++i)
        scene.push_back(facingPanel({u(rng) * 6, 1 + u(rng) * 2, -3 - 6 * (u(rng) + 1)}, {0.3f + u(rng) * 0.2f, 0.3f + u(rng) * 0.2f}));
    for (uint32_t atlas : {1024u, 256u, 48u}) {  // fits, scales, drops
        std::vector<uint32_t> idx = allIndices(scene.size());
        const GlassAtlasLayout a = pack(scene, idx, v, atlas);
        const GlassAtlasLayout b = pack(scene, idx, v, atlas);
        expectValidLayout(a, atlas);
        EXPECT_EQ(a.visible, 40u);
        const bool fits = a.scale == 1.0f, scales = a.scale < 1.0f && a.scale > kMinGlassScale && a.dropped == 0,
                   drops = a.scale == kMinGlassScale && a.dropped > 0;
        EXPECT_TRUE(atlas == 1024 ? fits : atlas == 256 ? scales : drops) << atlas;
        EXPECT_TRUE(sameLayout(a, b)) << atlas;
        std::shuffle(idx.begin(), idx.end(), rng);
        EXPECT_TRUE(sameLayout(a, pack(scene, idx, v, atlas))) << atlas << ": input order changed the layout";
    }
}

TEST(GlassAtlas, AtlasFromScreenRoundTrip) {
    GlassRegion r;
    r.screen = {50, 60, 350, 260};
    r.atlasOrigin = {100, 200};
    r.scale = 0.37f;
    r.atlasSize = expectedAtlasSize(r.screen, r.scale);
    EXPECT_EQ(atlasFromScreen(r, {50, 60}), glm::vec2(100, 200));
    const glm::vec2 far = atlasFromScreen(r, {350, 260});
    EXPECT_NEAR(far.x, 100 + 300 * 0.37f, 1e-3f);
    EXPECT_NEAR(far.y, 200 + 200 * 0.37f, 1e-3f);
    std::mt19937 rng(3u);
    std::uniform_real_distribution<float> px(0.0f, 400.0f);
    for (int i = 0; i < 1000; ++i) {
        const glm::vec2 p{px(rng), px(rng)};
        const glm::vec2 back = screenFromAtlas(r, atlasFromScreen(r, p));
        EXPECT_NEAR(back.x, p.x, 1e-3f);
        EXPECT_NEAR(back.y, p.y, 1e-3f);
    }
    r.scale = 1.0f;  // full resolution is a pure translation
    EXPECT_EQ(atlasFromScreen(r, {51.5f, 61.5f}), glm::vec2(101.5f, 201.5f));
    EXPECT_EQ(screenFromAtlas(r, {101.5f, 201.5f}), glm::vec2(51.5f, 61.5f));
}

// PPR's resolve writes each region and a one-texel ring around it and nothing else; the ring must
// stay out of every other region (it lies in the packer's gutter) and be clipped to the atlas.
TEST(GlassAtlas, DefinedTexelsAreTheRegionsAndTheirRings) {
    std::mt19937 rng(29u);
    std::uniform_int_distribution<int> side(1, 90), count(1, 16);
    int rings = 0, clipped = 0;
    for (int c = 0; c < 400; ++c) {
        std::vector<glm::ivec2> sizes(size_t(count(rng)));
        for (glm::ivec2& s : sizes) s = {side(rng), side(rng)};
        const auto origins = packRects(sizes, 256);
        if (!origins) continue;
        std::vector<GlassRegion> regions(sizes.size());
        for (size_t i = 0; i < sizes.size(); ++i) {
            regions[i].atlasOrigin = (*origins)[i];
            regions[i].atlasSize = sizes[i];
        }
        const std::vector<ScreenRect> defined = glassAtlasDefinedRects(regions, 256);
        ASSERT_EQ(defined.size(), regions.size());
        for (size_t i = 0; i < regions.size(); ++i) {
            const glm::ivec2 lo = regions[i].atlasOrigin, hi = lo + regions[i].atlasSize;
            const ScreenRect& d = defined[i];
            EXPECT_EQ(d, (ScreenRect{std::max(lo.x - 1, 0), std::max(lo.y - 1, 0), std::min(hi.x + 1, 256), std::min(hi.y + 1, 256)}));
            clipped += d.x0 == lo.x || d.y0 == lo.y || d.x1 == hi.x || d.y1 == hi.y;
            ++rings;
            for (size_t k = 0; k < regions.size(); ++k) {
                if (k == i) continue;
                const glm::ivec2 klo = regions[k].atlasOrigin, khi = klo + regions[k].atlasSize;
                const bool overlaps = d.x0 < khi.x && klo.x < d.x1 && d.y0 < khi.y && klo.y < d.y1;
                EXPECT_FALSE(overlaps) << "case " << c << ": region " << i << "'s ring reaches into region " << k;
            }
        }
    }
    EXPECT_GT(rings, 1000);
    EXPECT_GT(clipped, 100) << "regions on the atlas's edges";
}
