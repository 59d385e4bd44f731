// The projection pass's plane grid (passes/ppr_common/plane_grid.h): a point that a reflector's
// rectangle holds (reflectorContains, the pass's exact test) always falls in one of the cells the
// reflector marks, however the grid is placed, and the grid does separate a floor of tiles.
#include "common/reflector_data.h"
#include "ppr_common/plane_grid.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

namespace {

using glm::vec3;
using ppr::gpu::PprPlaneGrid;
using ppr::gpu::ReflectorData;

struct Rng {
    std::mt19937 gen;
    explicit Rng(uint32_t seed) : gen(seed) {}
    float uni(float a, float b) { return std::uniform_real_distribution<float>(a, b)(gen); }
    float logUni(float a, float b) { return std::exp(uni(std::log(a), std::log(b))); }
    vec3 unit() {
        for (;;) {
            vec3 v(uni(-1, 1), uni(-1, 1), uni(-1, 1));
            if (glm::dot(v, v) > 0.01f && glm::dot(v, v) <= 1.0f) return glm::normalize(v);
        }
    }
};

ReflectorData rectangle(vec3 center, vec3 normal, vec3 tangent, float hu, float hv) {
    ReflectorData r{};
    r.center = center;
    r.normal = normal;
    r.tangent = tangent;
    r.bitangent = glm::cross(normal, tangent);
    r.halfExtentU = hu;
    r.halfExtentV = hv;
    return r;
}

bool inRange(uint32_t cell, glm::uvec4 range) {
    const uint32_t x = cell % ppr::gpu::kPprPlaneGridSize, y = cell / ppr::gpu::kPprPlaneGridSize;
    return x >= range.x && x <= range.z && y >= range.y && y <= range.w;
}

// Points the shader would test: the crossing of the eye → mirror-image ray with the leader's plane,
// computed as ppr_project.comp's mirrorInPlane does, for pixels near and on the rectangle's edges.
TEST(PprPlaneGrid, EveryContainedHitFallsInAMarkedCell) {
    Rng rng(20261127);
    int contained = 0;
    for (int trial = 0; trial < 4000; ++trial) {
        const float scale = rng.logUni(0.01f, 500.0f);
        const vec3 normal = rng.unit();
        vec3 axis = glm::normalize(glm::cross(normal, rng.unit()));
        const vec3 leaderCenter = rng.unit() * rng.uni(0.0f, 3.0f) * scale;
        const ReflectorData leader = rectangle(leaderCenter, normal, axis, scale, scale);
        // A coplanar reflector (cull planes allow 10 µm), turned in the plane, somewhere near.
        const float turn = rng.uni(0.0f, 6.2832f);
        const vec3 tangent = glm::normalize(std::cos(turn) * leader.tangent + std::sin(turn) * leader.bitangent);
        const vec3 offset = (leader.tangent * rng.uni(-2, 2) + leader.bitangent * rng.uni(-2, 2)) * scale + normal * rng.uni(-1e-5f, 1e-5f);
        const ReflectorData r = rectangle(leaderCenter + offset, normal, tangent, rng.logUni(0.001f, 1.0f) * scale, rng.logUni(0.001f, 1.0f) * scale);
        // The grid: sometimes around the reflector, sometimes elsewhere, tiny, empty or inverted.
        vec3 lo = leaderCenter + (rng.unit() * rng.uni(0.0f, 2.0f) - vec3(1.0f)) * scale, hi = lo + vec3(rng.uni(0, 3), rng.uni(0, 3), rng.uni(0, 3)) * scale;
        if (trial % 10 == 0) hi = lo;
        if (trial % 10 == 1) std::swap(lo, hi);
        const PprPlaneGrid g = ppr::gpu::pprPlaneGridOver(lo, hi, leader.tangent, leader.bitangent);
        const glm::uvec4 cells = ppr::gpu::pprPlaneGridCellsOf(g, r);
        ASSERT_LE(cells.x, cells.z);
        ASSERT_LE(cells.y, cells.w);
        ASSERT_LT(cells.z, ppr::gpu::kPprPlaneGridSize);
        ASSERT_LT(cells.w, ppr::gpu::kPprPlaneGridSize);
        const vec3 eye = leaderCenter + normal * rng.logUni(0.05f, 20.0f) * scale + rng.unit() * rng.uni(0.0f, 5.0f) * scale;
        for (int k = 0; k < 40; ++k) {
            // A target on the rectangle, often right at an edge, mirrored to a point above the plane.
            float a = rng.uni(-1.0f, 1.0f), b = rng.uni(-1.0f, 1.0f);
            if (k % 4 == 0) a = a < 0 ? -1.0f : 1.0f;
            if (k % 4 == 1) b = b < 0 ? -1.0f : 1.0f;
            const vec3 onRect = r.center + r.tangent * (a * r.halfExtentU) + r.bitangent * (b * r.halfExtentV);
            const vec3 p = onRect + (glm::normalize(onRect - eye) + 2.0f * normal * rng.uni(0.01f, 1.0f)) * rng.logUni(0.01f, 10.0f) * scale;
            const float d = glm::dot(p - leader.center, leader.normal);
            const float eyeHeight = glm::dot(eye - leader.center, leader.normal);
            if (d <= 0.0f || eyeHeight <= 0.0f) continue;
            const vec3 mirrored = p - 2.0f * d * leader.normal;
            const vec3 hit = glm::mix(eye, mirrored, eyeHeight / (eyeHeight + d));
            if (!ppr::gpu::reflectorContains(r, hit)) continue;
            ++contained;
            ASSERT_TRUE(inRange(ppr::gpu::pprPlaneGridCell(g, hit), cells))
                << "trial " << trial << ": a point the rectangle holds fell outside its cells " << cells.x << ".." << cells.z << " x "
                << cells.y << ".." << cells.w << " (cell " << ppr::gpu::pprPlaneGridCell(g, hit) << ")";
        }
    }
    EXPECT_GT(contained, 10000) << "the trials should produce many contained hits, edges included";
}

// Where a cell boundary runs along a rectangle's edge, rounding puts hits just beyond the edge that
// the exact test still accepts: the slack must take them in (boxes shrunk by a millionth of their
// coordinates fail this test).
TEST(PprPlaneGrid, HitsOnAnEdgeAlongACellBoundaryStayInside) {
    Rng rng(7);
    const vec3 up(0, 1, 0), east(1, 0, 0), south(0, 0, 1);
    int onEdge = 0;
    for (int trial = 0; trial < 2000; ++trial) {
        const float scale = rng.logUni(0.01f, 300.0f);
        const ReflectorData r = rectangle(vec3(rng.uni(-3, 3), rng.uni(-1, 1), rng.uni(-3, 3)) * scale, up, east,
                                          rng.logUni(0.01f, 1.0f) * scale, rng.logUni(0.01f, 1.0f) * scale);
        // The grid's middle boundary on each axis runs along the rectangle's far edges.
        const vec3 lo = r.center - vec3(r.halfExtentU, 0, r.halfExtentV), far = r.center + vec3(r.halfExtentU, 0, r.halfExtentV);
        const PprPlaneGrid g = ppr::gpu::pprPlaneGridOver(lo, far + (far - lo), east, south);
        const glm::uvec4 cells = ppr::gpu::pprPlaneGridCellsOf(g, r);
        const vec3 eye = r.center + vec3(rng.uni(-2, 2), rng.logUni(0.1f, 5.0f), rng.uni(-2, 2)) * scale;
        for (int k = 0; k < 50; ++k) {
            const bool alongU = k % 2 == 0;
            const float a = alongU ? 1.0f : rng.uni(-1, 1), b = alongU ? rng.uni(-1, 1) : 1.0f;
            const vec3 onRect = r.center + east * (a * r.halfExtentU) + south * (b * r.halfExtentV);
            const vec3 p = onRect + (glm::normalize(onRect - eye) + up * rng.uni(0.1f, 2.0f)) * rng.logUni(0.01f, 10.0f) * scale;
            const float d = glm::dot(p - r.center, up), eyeHeight = glm::dot(eye - r.center, up);
            const vec3 mirrored = p - 2.0f * d * up;
            const vec3 hit = glm::mix(eye, mirrored, eyeHeight / (eyeHeight + d));
            if (d <= 0.0f || !ppr::gpu::reflectorContains(r, hit)) continue;
            ++onEdge;
            ASSERT_TRUE(inRange(ppr::gpu::pprPlaneGridCell(g, hit), cells)) << "trial " << trial << " point " << k;
        }
    }
    EXPECT_GT(onEdge, 10000);
}

// A 16 x 16 floor of tiles under a grid spanning it: each tile marks the one or few cells around
// it (the grid separates them), and together they cover the whole grid.
TEST(PprPlaneGrid, SeparatesAFloorOfTiles) {
    const vec3 up(0, 1, 0), east(1, 0, 0);
    const PprPlaneGrid g = ppr::gpu::pprPlaneGridOver(vec3(-8, 0, -8), vec3(8, 0, 8), east, glm::cross(up, east));
    std::vector<int> marks(ppr::gpu::kPprPlaneGridSize * ppr::gpu::kPprPlaneGridSize, 0);
    for (int row = 0; row < 16; ++row)
        for (int col = 0; col < 16; ++col) {
            const ReflectorData r = rectangle(vec3(-7.5f + col, 0, -7.5f + row), up, east, 0.45f, 0.45f);
            const glm::uvec4 c = ppr::gpu::pprPlaneGridCellsOf(g, r);
            EXPECT_EQ(c.z - c.x + 1, 1u) << "tile " << col << "," << row << " spans one column of cells";
            EXPECT_EQ(c.w - c.y + 1, 1u) << "tile " << col << "," << row << " spans one row of cells";
            for (uint32_t y = c.y; y <= c.w; ++y)
                for (uint32_t x = c.x; x <= c.z; ++x) ++marks[x + y * ppr::gpu::kPprPlaneGridSize];
        }
    for (int m : marks) EXPECT_EQ(m, 4) << "each cell of an 8 x 8 grid over 16 x 16 tiles holds 2 x 2 of them";
}

// Degenerate and hostile spans leave the grid one cell wide on that axis, never NaN cells.
TEST(PprPlaneGrid, DegenerateSpansUseOneCell) {
    const vec3 up(0, 1, 0), east(1, 0, 0), south(0, 0, 1);
    const float inf = std::numeric_limits<float>::infinity();
    for (const auto& [lo, hi] : {std::pair{vec3(0), vec3(0)}, std::pair{vec3(1), vec3(-1)}, std::pair{vec3(-inf), vec3(inf)},
                                 std::pair{vec3(-1e30f), vec3(1e30f)}}) {
        const PprPlaneGrid g = ppr::gpu::pprPlaneGridOver(lo, hi, east, south);
        EXPECT_EQ(g.scale.x, 0.0f);
        EXPECT_EQ(g.scale.y, 0.0f);
        EXPECT_EQ(ppr::gpu::pprPlaneGridCell(g, vec3(123, 0, -4)), 0u);
        EXPECT_EQ(ppr::gpu::pprPlaneGridCellsOf(g, rectangle(vec3(5, 0, 5), up, east, 1, 1)), glm::uvec4(0));
    }
    // Points far beyond a proper grid land in its border cells.
    const PprPlaneGrid g = ppr::gpu::pprPlaneGridOver(vec3(0), vec3(8, 0, 8), east, south);
    EXPECT_EQ(ppr::gpu::pprPlaneGridCell(g, vec3(-1e20f, 0, 1e20f)), ppr::gpu::kPprPlaneGridSize * (ppr::gpu::kPprPlaneGridSize - 1));
}

}  // namespace
