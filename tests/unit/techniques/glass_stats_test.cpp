// What the glass passes dispatch over: the atlas rows and columns the packed regions fill
// (app/frame/glass_atlas_frame.hpp); the texels beyond them keep the clear.
#include "frame/glass_atlas_frame.hpp"

#include <gtest/gtest.h>

using ppr::app::GlassStats;

namespace {
ppr::scene::GlassRegion region(glm::ivec2 origin, glm::ivec2 size) {
    ppr::scene::GlassRegion r;
    r.atlasOrigin = origin;
    r.atlasSize = size;
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
