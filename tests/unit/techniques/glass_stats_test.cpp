// What the glass passes dispatch over: the atlas rows and columns the packed regions fill
// (app/frame/glass_atlas_frame.hpp), or PPR's resolve, the regions' blocks one after another
// (passes/glass_reflect/glass_regions.hpp); the texels beyond them keep the clear.
#include "frame/glass_atlas_frame.hpp"
#include "glass_reflect/glass_reflect.h"
#include "glass_reflect/glass_regions.hpp"

#include <gtest/gtest.h>

using ppr::app::GlassStats;

namespace {
ppr::scene::GlassRegion region(glm::ivec2 origin, glm::ivec2 size, uint32_t reflector = 0) {
    ppr::scene::GlassRegion r;
    r.atlasOrigin = origin;
    r.atlasSize = size;
    r.reflectorIndex = reflector;
    return r;
}
}  // namespace

TEST(GlassStats, UsedExtentIsTheFarthestRegionEdgeOnEachAxis) {
    GlassStats stats;
    stats.atlasSize = 1024;
    EXPECT_EQ(stats.usedExtent().width, 0u);
    EXPECT_EQ(stats.usedExtent().height, 0u);
    stats.layout = {region({0, 0}, {130, 500}), region({130, 0}, {250, 240}), region({0, 500}, {90, 20})};
    EXPECT_EQ(stats.usedExtent().width, 380u);   // the second region's right edge
    EXPECT_EQ(stats.usedExtent().height, 520u);  // the third region's bottom edge
    stats.layout = {region({1000, 1000}, {24, 24})};
    EXPECT_EQ(stats.usedExtent().width, 1024u);
    EXPECT_EQ(stats.usedExtent().height, 1024u);
}

TEST(GlassRegionTable, TheResolveRunsEachRegionsBlocksOneRegionAfterAnother) {
    static_assert(ppr::gpu::kGlassReflectGroupSize == 16u, "the block counts below are for 16x16 blocks");
    ppr::passes::GlassRegionTable table;
    table.reserve(4);
    ppr::scene::GlassAtlasLayout layout;
    table.fill(layout);
    EXPECT_EQ(table.blockCount(), 0u);
    // Each region with its one-texel ring: 132x502: 9 x 32 blocks (partial ones count), 252x242:
    // 16 x 16, 18x18: 2 x 2; a reflector beyond the table gets no region and no block.
    layout.regions = {region({0, 0}, {130, 500}, 2), region({130, 0}, {250, 240}, 0), region({0, 500}, {16, 16}, 3),
                      region({0, 520}, {40, 40}, 9)};
    table.fill(layout);
    EXPECT_EQ(table.blockCount(), 288u + 256u + 4u);
    const std::vector<uint32_t>& starts = table.blockStarts();
    ASSERT_EQ(starts.size(), 5u);
    EXPECT_EQ(starts[0], 0u);
    EXPECT_EQ(starts[1], 288u);
    EXPECT_EQ(starts[2], 544u);
    EXPECT_EQ(starts[3], 548u);  // after the last listed region: the total
}
