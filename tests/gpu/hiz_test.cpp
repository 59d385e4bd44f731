// ssr-hiz on the GPU: the depth hierarchy the frame builds is exactly the min-reduction of its depth
// buffer (hiz/hiz.h layout: levels 1.. in the atlas, odd sizes included, every hiz_threads), with the
// far values of its 8x8 cells beside level 2, and the hierarchical march finds the reflections
// ssr-brute finds, with the same colours. Validation + synchronization validation on throughout.
#include "common/reflection.h"
#include "gpu_test_util.hpp"
#include "hiz/hiz.h"
#include "hiz/hiz_threads.hpp"
#include "tonemap/tonemap.h"

#include <algorithm>
#include <cmath>

namespace ppr::test {
namespace {

// Every level texel of the read-back atlas against the min over the level-0 values it covers,
// computed on the CPU from the read-back depth (min is exact, so equality is exact).
void expectAtlasIsMinOfDepth(const app::DepthCapture& c, const std::string& what) {
    const glm::uvec2 screen(c.width, c.height);
    const glm::uvec2 padded = gpu::hizPaddedSize(screen);
    const glm::uvec2 atlas = gpu::hizAtlasSize(padded);
    ASSERT_EQ(c.atlasWidth, atlas.x) << what;
    ASSERT_EQ(c.atlasHeight, atlas.y) << what;
    ASSERT_EQ(c.depth.size(), size_t(screen.x) * screen.y) << what;
    // The reduction level by level, each level from the CPU's level below (the oracle never reads
    // the GPU's atlas).
    std::vector<float> level(size_t(padded.x) * padded.y);
    for (uint32_t y = 0; y < padded.y; ++y)
        for (uint32_t x = 0; x < padded.x; ++x)
            level[size_t(y) * padded.x + x] = x < screen.x && y < screen.y ? gpu::hizFromReverseZ(c.depth[size_t(y) * screen.x + x]) : gpu::kHizEmpty;
    size_t sky = 0, mismatches = 0, edgeQuads = 0;
    for (float d : c.depth) sky += d == 0.0f;
    for (uint32_t l = 0; l < gpu::kHizLevels; ++l) {
        const glm::uvec2 size = gpu::hizLevelSize(padded, l);
        if (l > 0) {
            const uint32_t below = size.x * 2;
            std::vector<float> next(size_t(size.x) * size.y);
            for (uint32_t y = 0; y < size.y; ++y)
                for (uint32_t x = 0; x < size.x; ++x) {
                    const size_t s = size_t(2 * y) * below + 2 * x;
                    next[size_t(y) * size.x + x] = std::min(std::min(level[s], level[s + 1]), std::min(level[s + below], level[s + below + 1]));
                }
            level = std::move(next);
        }
        if (l == 0) continue;  // level 0 is the depth buffer itself, not in the atlas
        const glm::ivec2 origin = gpu::hizLevelOrigin(padded, l);
        for (uint32_t y = 0; y < size.y; ++y)
            for (uint32_t x = 0; x < size.x; ++x) {
                const float expected = level[size_t(y) * size.x + x];
                const float got = c.hizAtlas[size_t(origin.y + y) * atlas.x + origin.x + x];
                if (got != expected && ++mismatches <= 5)
                    ADD_FAILURE() << what << ": level " << l << " texel " << x << "," << y << " is " << got << ", expected " << expected;
                // Level 1 quads that reach past the screen take the build's per-texel path.
                if (l == 1 && (2 * x + 1 >= screen.x || 2 * y + 1 >= screen.y)) ++edgeQuads;
            }
    }
    // The far values of the 8x8 cells beside level 2: the least depth on screen in each (sky is 0).
    const glm::uvec2 farSize = gpu::hizLevelSize(padded, gpu::kHizFarLevel);
    const glm::ivec2 farOrigin = gpu::hizFarOrigin(padded);
    const uint32_t side = 1u << gpu::kHizFarLevel;
    size_t farSkyCells = 0;
    for (uint32_t y = 0; y < farSize.y; ++y)
        for (uint32_t x = 0; x < farSize.x; ++x) {
            float expected = gpu::kHizFarNone;
            for (uint32_t py = y * side; py < (y + 1) * side && py < screen.y; ++py)
                for (uint32_t px = x * side; px < (x + 1) * side && px < screen.x; ++px) expected = std::min(expected, c.depth[size_t(py) * screen.x + px]);
            farSkyCells += expected == 0.0f;
            const float got = c.hizAtlas[size_t(farOrigin.y + y) * atlas.x + farOrigin.x + x];
            if (got != expected && ++mismatches <= 5)
                ADD_FAILURE() << what << ": far value of cell " << x << "," << y << " is " << got << ", expected " << expected;
        }
    EXPECT_GT(farSkyCells, 0u) << what;
    EXPECT_EQ(mismatches, 0u) << what;
    // The view is worth checking: some sky, some geometry.
    EXPECT_GT(sky, 0u) << what;
    EXPECT_LT(sky, c.depth.size()) << what;
    if (screen.x % 64 || screen.y % 64) {
        EXPECT_GT(edgeQuads, 0u) << what;
    }
}

// (Suite `hiz`, lower case like the unit tests' folder, so `ctest -R hiz` runs both.)
// With every workgroup width hiz_threads offers (blocks of 16, 8 and 4 texels a side, so the walk
// stops at each of levels 4, 3 and 2 and the shared reduction does the rest), on screens of whole
// cells, of partial ones and of less than one.
TEST(hiz, AtlasIsTheMinReductionOfTheDepthBuffer) {
    GpuFixture f;
    f.headless->setTechnique("ssr-hiz");
    for (uint32_t threads : passes::kHizThreadChoices) {
        f.headless->settings().set("hiz_threads", std::to_string(threads));
        for (VkExtent2D size : {VkExtent2D{320, 180}, VkExtent2D{203, 117}, VkExtent2D{61, 37}})
            for (const char* camera : {"overview", "puddles"}) {
                const app::DepthCapture c = f.headless->captureDepth(f.camera(camera), size);
                expectAtlasIsMinOfDepth(c, std::string(camera) + " " + std::to_string(size.width) + "x" + std::to_string(size.height) +
                                               " hiz_threads=" + std::to_string(threads));
            }
    }
    EXPECT_EQ(f.ctx->validationErrors(), 0u);
}

// PPR's fallback: with one reach invocation per tile (reach_threads=1, a CPU device's default) the
// reach pass stores every tile's levels 1..4 and the build adds the padding and the levels above, read
// back at the level of each width's blocks (16, 8, 4 texels a side); with 4 the build does it all.
TEST(hiz, PprReachStoresTheSameHierarchy) {
    GpuFixture f;
    f.headless->setTechnique("ppr");
    for (const char* reachThreads : {"1", "4"})
        for (uint32_t threads : passes::kHizThreadChoices) {
            f.headless->settings().set("reach_threads", reachThreads);
            f.headless->settings().set("hiz_threads", std::to_string(threads));
            for (VkExtent2D size : {VkExtent2D{320, 180}, VkExtent2D{203, 117}, VkExtent2D{61, 37}}) {
                const app::DepthCapture c = f.headless->captureDepth(f.camera("overview"), size);
                expectAtlasIsMinOfDepth(c, "ppr " + std::to_string(size.width) + "x" + std::to_string(size.height) + " reach_threads=" +
                                               reachThreads + " hiz_threads=" + std::to_string(threads));
            }
        }
    EXPECT_EQ(f.ctx->validationErrors(), 0u);
}

TEST(hiz, NoHierarchyWithoutATechniqueThatUsesIt) {
    GpuFixture f;
    f.headless->setTechnique("ssr-brute");
    const app::DepthCapture c = f.headless->captureDepth(f.camera("overview"), {160, 90});
    EXPECT_EQ(c.atlasWidth, 0u);
    EXPECT_TRUE(c.hizAtlas.empty());
    EXPECT_EQ(c.depth.size(), size_t(160) * 90);
    EXPECT_EQ(f.ctx->validationErrors(), 0u);
}

}  // namespace
}  // namespace ppr::test
