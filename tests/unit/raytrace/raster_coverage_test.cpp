// The rasterizer's coverage rule that the ray-traced reference's rt_coverage=raster applies to its
// candidate triangles (passes/raytrace/raster_coverage.h). A rasterizer must cover a pixel centre with
// exactly one triangle of a mesh that surrounds it, whether the centre lies inside a triangle, on a
// shared edge or on a shared vertex: that is what the top-left rule is for, and what lets the ray tracer
// pick the same triangle as the planar reference's rasterizer on the edges the snapped corners move.
#include "raytrace/raster_coverage.h"

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <random>
#include <vector>

namespace {

using glm::ivec2;
using ppr::gpu::kRasterMaxCorners;
using ppr::gpu::rasterCoversCentre;
using ppr::gpu::rasterCrossSign;

bool covers(ivec2 a, ivec2 b, ivec2 c) {
    ivec2 q[kRasterMaxCorners] = {a, b, c, ivec2(0)};
    return rasterCoversCentre(q, 3);
}

int sign64(int64_t v) { return v > 0 ? 1 : (v < 0 ? -1 : 0); }

TEST(RasterCoverage, CrossSignIsExactWhereAFloatIsNot) {
    std::mt19937 rng(7);
    std::uniform_int_distribution<int> coordinate(-(1 << 30), 1 << 30);
    for (int i = 0; i < 100000; ++i) {
        const ivec2 a(coordinate(rng), coordinate(rng)), b(coordinate(rng), coordinate(rng));
        ASSERT_EQ(rasterCrossSign(a, b), sign64(int64_t(a.x) * b.y - int64_t(a.y) * b.x)) << i;
    }
    // Nearly parallel, 2^26 from the centre: the products differ by 1, far below a float's resolution.
    const ivec2 a((1 << 26) + 1, 1 << 26), b(1 << 26, (1 << 26) - 1);
    EXPECT_EQ(rasterCrossSign(a, b), -1);
    EXPECT_EQ(float(a.x) * float(b.y) - float(a.y) * float(b.x), 0.0f) << "the case a float gets wrong";
    EXPECT_EQ(rasterCrossSign(a, a), 0);
}

TEST(RasterCoverage, TopAndLeftEdgesTakeTheCentresOnThem) {
    // y points down. A horizontal edge through the centre: the triangle below it (a top edge) covers the
    // centre, the one above does not; a vertical edge: the triangle to its right (a left edge) covers it.
    EXPECT_TRUE(covers(ivec2(-100, 0), ivec2(100, 0), ivec2(0, 100)));
    EXPECT_FALSE(covers(ivec2(-100, 0), ivec2(100, 0), ivec2(0, -100)));
    EXPECT_TRUE(covers(ivec2(0, -100), ivec2(0, 100), ivec2(100, 0)));
    EXPECT_FALSE(covers(ivec2(0, -100), ivec2(0, 100), ivec2(-100, 0)));
    // Either winding gives the same answer.
    EXPECT_TRUE(covers(ivec2(100, 0), ivec2(-100, 0), ivec2(0, 100)));
    EXPECT_FALSE(covers(ivec2(0, 100), ivec2(0, -100), ivec2(-100, 0)));
    // Inside, outside, degenerate.
    EXPECT_TRUE(covers(ivec2(-10, -10), ivec2(10, -10), ivec2(0, 10)));
    EXPECT_FALSE(covers(ivec2(5, 5), ivec2(10, 5), ivec2(5, 10)));
    EXPECT_FALSE(covers(ivec2(-10, -10), ivec2(0, 0), ivec2(10, 10)));
}

TEST(RasterCoverage, AClippedQuadCoversAsItsTwoTriangles) {
    std::mt19937 rng(11);
    std::uniform_int_distribution<int> coordinate(-600, 600);
    int agreed = 0;
    for (int i = 0; i < 20000; ++i) {
        // A convex quad: a triangle cut by a line leaves one (corners in order).
        const std::array<ivec2, 4> c = {ivec2(-500, -400), ivec2(coordinate(rng), -450), ivec2(520, coordinate(rng) / 2 + 200),
                                        ivec2(-450, 480)};
        ivec2 q[kRasterMaxCorners] = {c[0], c[1], c[2], c[3]};
        const bool quad = rasterCoversCentre(q, 4);
        const int halves = int(covers(c[0], c[1], c[2])) + int(covers(c[0], c[2], c[3]));
        // With c[1] and c[3] on either side of the diagonal the two triangles only share it.
        if (rasterCrossSign(c[2] - c[0], c[1] - c[0]) * rasterCrossSign(c[2] - c[0], c[3] - c[0]) < 0 && halves > 1)
            FAIL() << "a centre on the diagonal covered twice, case " << i;
        // The two triangles are the quad split along a diagonal: where the quad is convex they agree.
        if (rasterCrossSign(c[1] - c[0], c[2] - c[0]) * rasterCrossSign(c[2] - c[0], c[3] - c[0]) > 0 &&
            rasterCrossSign(c[2] - c[1], c[3] - c[1]) * rasterCrossSign(c[3] - c[1], c[0] - c[1]) > 0) {
            EXPECT_EQ(quad, halves == 1) << i;
            ++agreed;
        }
    }
    EXPECT_GT(agreed, 10000);
}

// A jittered grid of corners around the centre, two triangles per cell, shifted so that the centre
// falls inside a triangle, on an edge, or on a corner: exactly one triangle covers it.
TEST(RasterCoverage, AMeshCoversEveryCentreExactlyOnce) {
    std::mt19937 rng(3);
    constexpr int kCells = 6, kSpacing = 256;  // one pixel at 8 sub-pixel bits
    std::uniform_int_distribution<int> jitter(-60, 60), pick(0, 2);
    int onCorner = 0, onEdge = 0;
    for (int trial = 0; trial < 4000; ++trial) {
        std::vector<ivec2> p((kCells + 1) * (kCells + 1));
        for (int y = 0; y <= kCells; ++y)
            for (int x = 0; x <= kCells; ++x) {
                const bool border = x == 0 || y == 0 || x == kCells || y == kCells;
                // Some interior corners stay on the lattice so that edges run exactly along its lines.
                const bool onLattice = pick(rng) == 0;
                p[y * (kCells + 1) + x] = ivec2(x, y) * kSpacing + (border || onLattice ? ivec2(0) : ivec2(jitter(rng), jitter(rng)));
            }
        // The centre: a random interior point, a corner, or a point halfway along a lattice edge.
        ivec2 centre;
        const int kind = pick(rng);
        const int cx = 2 + int(rng() % 3), cy = 2 + int(rng() % 3);
        if (kind == 0) centre = ivec2(kSpacing * 2 + int(rng() % (kSpacing * 2)), kSpacing * 2 + int(rng() % (kSpacing * 2)));
        else if (kind == 1) centre = p[cy * (kCells + 1) + cx];
        else centre = (p[cy * (kCells + 1) + cx] + p[cy * (kCells + 1) + cx + 1]) / 2;
        int count = 0;
        for (int y = 0; y < kCells; ++y)
            for (int x = 0; x < kCells; ++x) {
                const ivec2 a = p[y * (kCells + 1) + x] - centre, b = p[y * (kCells + 1) + x + 1] - centre;
                const ivec2 c = p[(y + 1) * (kCells + 1) + x] - centre, d = p[(y + 1) * (kCells + 1) + x + 1] - centre;
                // Alternate diagonals, and both windings, as a mesh would have them.
                if ((x + y) % 2 == 0) count += int(covers(a, b, d)) + int(covers(a, c, d));
                else count += int(covers(b, a, c)) + int(covers(b, d, c));
            }
        ASSERT_EQ(count, 1) << "trial " << trial << ", centre kind " << kind;
        onCorner += kind == 1;
        onEdge += kind == 2;
    }
    EXPECT_GT(onCorner, 1000);
    EXPECT_GT(onEdge, 1000);
}

}  // namespace
