// The depth hierarchy's layout (passes/hiz/hiz.h, the header hiz_build.comp and ssr_hiz.comp
// compile): padding, where levels 1.. sit in the atlas (level 0 is the depth buffer), and that a
// build following it makes every texel the nearest depth of the pixels it covers.
#include "hiz/hiz.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

using namespace ppr::gpu;

namespace {

constexpr uint32_t kCoarsestCell = 1u << (kHizLevels - 1u);

// Screen sizes worth checking: every size up to a few coarse cells, odd sizes and real ones.
std::vector<glm::uvec2> screenSizes() {
    std::vector<glm::uvec2> sizes;
    for (uint32_t w = 1; w <= 200; w += 3)
        for (uint32_t h = 1; h <= 200; h += 7) sizes.push_back({w, h});
    for (glm::uvec2 s : {glm::uvec2(64, 64), glm::uvec2(65, 64), glm::uvec2(320, 180), glm::uvec2(203, 117), glm::uvec2(1280, 720),
                         glm::uvec2(1920, 1080), glm::uvec2(2560, 1440), glm::uvec2(3840, 2160), glm::uvec2(4095, 4095)})
        sizes.push_back(s);
    return sizes;
}

struct Rect {
    glm::ivec2 origin;
    glm::uvec2 size;
};

bool overlap(const Rect& a, const Rect& b) {
    return a.origin.x < b.origin.x + int(b.size.x) && b.origin.x < a.origin.x + int(a.size.x) && a.origin.y < b.origin.y + int(b.size.y) &&
           b.origin.y < a.origin.y + int(a.size.y);
}

// Level 0, the depth buffer as the march reads it: 1 − depth on screen, empty beyond.
float level0(const std::vector<float>& depth, glm::uvec2 screen, uint32_t x, uint32_t y) {
    return x < screen.x && y < screen.y ? hizFromReverseZ(depth[size_t(y) * screen.x + x]) : kHizEmpty;
}

// The atlas as the GPU build makes it, level by level: level 1 the minimum of each 2×2 quad of level
// 0, every other level the minimum of the 2×2 texels below. Texels outside every level stay NaN.
std::vector<float> buildAtlas(const std::vector<float>& depth, glm::uvec2 screen) {
    const glm::uvec2 padded = hizPaddedSize(screen);
    const glm::uvec2 atlasSize = hizAtlasSize(padded);
    std::vector<float> atlas(size_t(atlasSize.x) * atlasSize.y, std::nanf(""));
    auto at = [&](glm::ivec2 p) -> float& { return atlas[size_t(p.y) * atlasSize.x + p.x]; };
    for (uint32_t level = 1; level < kHizLevels; ++level) {
        const glm::ivec2 dst = hizLevelOrigin(padded, level);
        const glm::uvec2 size = hizLevelSize(padded, level);
        for (uint32_t y = 0; y < size.y; ++y)
            for (uint32_t x = 0; x < size.x; ++x) {
                float v;
                if (level == 1) {
                    v = std::min(std::min(level0(depth, screen, 2 * x, 2 * y), level0(depth, screen, 2 * x + 1, 2 * y)),
                                 std::min(level0(depth, screen, 2 * x, 2 * y + 1), level0(depth, screen, 2 * x + 1, 2 * y + 1)));
                } else {
                    const glm::ivec2 s = hizLevelOrigin(padded, level - 1) + 2 * glm::ivec2(x, y);
                    v = std::min(std::min(at(s), at(s + glm::ivec2(1, 0))), std::min(at(s + glm::ivec2(0, 1)), at(s + glm::ivec2(1, 1))));
                }
                at(dst + glm::ivec2(x, y)) = v;
            }
    }
    return atlas;
}

// Reverse-Z depth with sky (0), a spread of distances and a few near pixels.
std::vector<float> randomDepth(glm::uvec2 screen, uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::vector<float> depth(size_t(screen.x) * screen.y);
    for (float& d : depth) {
        const float r = u(rng);
        if (r < 0.2f) d = 0.0f;                       // sky
        else if (r < 0.25f) d = 0.5f + 0.5f * u(rng);  // near
        else d = 0.001f + 0.1f * u(rng);              // far: values close together near 1 after 1 − z
    }
    return depth;
}

}  // namespace

TEST(HizLayout, SkyAndPaddingAreEmpty) {
    EXPECT_EQ(hizFromReverseZ(0.0f), kHizEmpty);
    const std::vector<float> depth(size_t(5) * 3, 0.5f);
    EXPECT_EQ(level0(depth, {5, 3}, 4, 2), hizFromReverseZ(0.5f));
    EXPECT_EQ(level0(depth, {5, 3}, 5, 2), kHizEmpty);  // padding
    EXPECT_EQ(level0(depth, {5, 3}, 4, 3), kHizEmpty);
    EXPECT_EQ(hizFromReverseZ(1.0f), 0.0f);  // at the near plane
    EXPECT_LT(hizFromReverseZ(0.5f), hizFromReverseZ(0.25f));  // nearer is smaller: the min is the nearest
}

TEST(HizLayout, PaddedSizeIsTheScreenRoundedUpToTheCoarsestCell) {
    for (glm::uvec2 screen : screenSizes()) {
        const glm::uvec2 padded = hizPaddedSize(screen);
        for (int axis = 0; axis < 2; ++axis) {
            EXPECT_EQ(padded[axis] % kCoarsestCell, 0u) << screen.x << "x" << screen.y;
            EXPECT_GE(padded[axis], screen[axis]) << screen.x << "x" << screen.y;
            EXPECT_LT(padded[axis] - screen[axis], kCoarsestCell) << screen.x << "x" << screen.y;
        }
    }
}

TEST(HizLayout, EveryLevelIsExactlyHalfTheOneBelow) {
    for (glm::uvec2 screen : screenSizes()) {
        const glm::uvec2 padded = hizPaddedSize(screen);
        EXPECT_EQ(hizLevelSize(padded, 0), padded);
        for (uint32_t level = 1; level < kHizLevels; ++level) {
            EXPECT_EQ(hizLevelSize(padded, level) * 2u, hizLevelSize(padded, level - 1)) << screen.x << "x" << screen.y << " level " << level;
            EXPECT_GE(hizLevelSize(padded, level).x, 1u);
            EXPECT_GE(hizLevelSize(padded, level).y, 1u);
        }
    }
}

TEST(HizLayout, LevelsFitInTheAtlasWithoutOverlapping) {
    for (glm::uvec2 screen : screenSizes()) {
        const glm::uvec2 padded = hizPaddedSize(screen);
        const glm::uvec2 atlas = hizAtlasSize(padded);
        std::vector<Rect> rects;
        for (uint32_t level = 1; level < kHizLevels; ++level) {
            const Rect r{hizLevelOrigin(padded, level), hizLevelSize(padded, level)};
            EXPECT_GE(r.origin.x, 0);
            EXPECT_GE(r.origin.y, 0);
            EXPECT_LE(r.origin.x + int(r.size.x), int(atlas.x)) << screen.x << "x" << screen.y << " level " << level;
            EXPECT_LE(r.origin.y + int(r.size.y), int(atlas.y)) << screen.x << "x" << screen.y << " level " << level;
            for (size_t other = 0; other < rects.size(); ++other)
                EXPECT_FALSE(overlap(r, rects[other])) << screen.x << "x" << screen.y << ": levels " << other + 1 << " and " << level;
            rects.push_back(r);
        }
        // The far values of the 8x8 cells, beside level 2, overlap no level either.
        const Rect far{hizFarOrigin(padded), hizLevelSize(padded, kHizFarLevel)};
        EXPECT_LE(far.origin.x + int(far.size.x), int(atlas.x)) << screen.x << "x" << screen.y;
        EXPECT_LE(far.origin.y + int(far.size.y), int(atlas.y)) << screen.x << "x" << screen.y;
        for (size_t other = 0; other < rects.size(); ++other)
            EXPECT_FALSE(overlap(far, rects[other])) << screen.x << "x" << screen.y << ": the far values and level " << other + 1;
    }
}

TEST(HizLayout, BuiltChainHoldsTheNearestDepthOfEveryCell) {
    const glm::uvec2 sizes[] = {{37, 23}, {1, 1}, {65, 64}, {130, 7}, {64, 64}, {7, 130}, {129, 65}};
    uint32_t seed = 1;
    for (glm::uvec2 screen : sizes) {
        for (int variant = 0; variant < 3; ++variant, ++seed) {
            const std::vector<float> depth = randomDepth(screen, seed);
            const std::vector<float> atlas = buildAtlas(depth, screen);
            const glm::uvec2 padded = hizPaddedSize(screen);
            const glm::uvec2 atlasSize = hizAtlasSize(padded);
            // Brute force: the min over every level-0 texel the cell covers, straight from the depth.
            uint64_t checked = 0;
            for (uint32_t level = 1; level < kHizLevels; ++level) {
                const glm::ivec2 origin = hizLevelOrigin(padded, level);
                const glm::uvec2 size = hizLevelSize(padded, level);
                const uint32_t cell = 1u << level;
                for (uint32_t cy = 0; cy < size.y; ++cy)
                    for (uint32_t cx = 0; cx < size.x; ++cx) {
                        float expected = INFINITY;
                        for (uint32_t y = cy * cell; y < (cy + 1) * cell; ++y)
                            for (uint32_t x = cx * cell; x < (cx + 1) * cell; ++x) expected = std::min(expected, level0(depth, screen, x, y));
                        const float got = atlas[size_t(origin.y + cy) * atlasSize.x + origin.x + cx];
                        ASSERT_EQ(got, expected) << screen.x << "x" << screen.y << " seed " << seed << " level " << level << " cell " << cx << ","
                                                 << cy;
                        ++checked;
                    }
            }
            // Every texel of every level was written and checked.
            uint64_t texels = 0;
            for (uint32_t level = 1; level < kHizLevels; ++level) texels += uint64_t(hizLevelSize(padded, level).x) * hizLevelSize(padded, level).y;
            EXPECT_EQ(checked, texels);
        }
    }
}

TEST(HizLayout, CellsOnTheScreenEdgeSeeOnlyTheScreen) {
    // All sky but the bottom-right pixel: that pixel shows up in the one cell of each level that
    // covers it, and the padding beyond it (empty) changes nothing.
    const glm::uvec2 screen(37, 23);
    std::vector<float> depth(size_t(screen.x) * screen.y, 0.0f);
    depth[size_t(22) * screen.x + 36] = 0.75f;  // the bottom-right pixel
    const std::vector<float> atlas = buildAtlas(depth, screen);
    const glm::uvec2 padded = hizPaddedSize(screen);
    const glm::uvec2 atlasSize = hizAtlasSize(padded);
    for (uint32_t level = 1; level < kHizLevels; ++level) {
        const glm::ivec2 origin = hizLevelOrigin(padded, level);
        const glm::uvec2 size = hizLevelSize(padded, level);
        const glm::uvec2 nearCell(36u >> level, 22u >> level);
        for (uint32_t cy = 0; cy < size.y; ++cy)
            for (uint32_t cx = 0; cx < size.x; ++cx) {
                const float v = atlas[size_t(origin.y + cy) * atlasSize.x + origin.x + cx];
                EXPECT_EQ(v, glm::uvec2(cx, cy) == nearCell ? hizFromReverseZ(0.75f) : kHizEmpty) << "level " << level;
            }
    }
}
