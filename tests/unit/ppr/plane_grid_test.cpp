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
    bool chance(float p) { return uni(0.0f, 1.0f) < p; }
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

// The projection's contract (ppr_project.comp, projectTileOnGrid): a pixel whose hit in a coplanar
// reflector's own plane lies in its rectangle (the scan's exact test) finds that reflector among the
// cells around its hit in the plane leader's plane, within pprPlaneGridLookupMargin. Pixels near and
// on the rectangle's edges, rays down to grazing, planes up to the cull-plane tolerance apart.
TEST(PprPlaneGrid, EveryReflectorThatTakesAPixelIsLookedUp) {
    Rng rng(20261127);
    int contained = 0, grazing = 0;
    for (int trial = 0; trial < 4000; ++trial) {
        const float scale = rng.logUni(0.01f, 500.0f);
        const vec3 normal = rng.unit();
        vec3 axis = glm::normalize(glm::cross(normal, rng.unit()));
        const vec3 leaderCenter = rng.unit() * rng.uni(0.0f, 3.0f) * scale;
        const ReflectorData leader = rectangle(leaderCenter, normal, axis, scale, scale);
        // A coplanar reflector (cull planes allow kPprCullPlaneTolerance), turned in the plane, somewhere near.
        const float turn = rng.uni(0.0f, 6.2832f);
        const vec3 tangent = glm::normalize(std::cos(turn) * leader.tangent + std::sin(turn) * leader.bitangent);
        const float tolerance = ppr::gpu::kPprCullPlaneTolerance;
        const vec3 offset = (leader.tangent * rng.uni(-2, 2) + leader.bitangent * rng.uni(-2, 2)) * scale + normal * (rng.chance(0.8f) ? (rng.chance(0.5f) ? tolerance : -tolerance) : rng.uni(-tolerance, tolerance));
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
        // Eye heights down to a millionth of the scene's size: grazing rays.
        const vec3 eye = leaderCenter + normal * rng.logUni(1e-7f, 20.0f) * scale + rng.unit() * rng.uni(0.0f, 5.0f) * scale;
        for (int k = 0; k < 40; ++k) {
            // A target on the rectangle, often right at an edge, mirrored to a point above the plane.
            float a = rng.uni(-1.0f, 1.0f), b = rng.uni(-1.0f, 1.0f);
            if (k % 4 == 0) a = a < 0 ? -1.0f : 1.0f;
            if (k % 4 == 1) b = b < 0 ? -1.0f : 1.0f;
            const vec3 onRect = r.center + r.tangent * (a * r.halfExtentU) + r.bitangent * (b * r.halfExtentV);
            // The pixel's point lies on the ray from the mirrored eye through its hit.
            const vec3 mirroredEye = eye - 2.0f * glm::dot(eye - r.center, r.normal) * r.normal;
            const vec3 p = onRect + (onRect - mirroredEye) * rng.logUni(0.01f, 10.0f);
            // The scan's test in r's own plane (ppr_project.comp's takes()).
            const float d = glm::dot(p - r.center, r.normal), eyeHeight = glm::dot(eye - r.center, r.normal);
            if (d <= 1e-3f || eyeHeight <= 0.0f) continue;
            const vec3 hit = glm::mix(eye, p - 2.0f * d * r.normal, eyeHeight / (eyeHeight + d));
            if (!ppr::gpu::reflectorContains(r, hit)) continue;
            // The lookup in the leader's plane (projectTileOnGrid).
            const float height = glm::dot(p - leader.center, leader.normal), leaderEyeHeight = glm::dot(eye - leader.center, leader.normal);
            const float span = height + leaderEyeHeight;
            ASSERT_GT(span, 0.5e-3f) << "the grid path would give up on a pixel a reflector takes";
            const vec3 mirrored = p - 2.0f * height * leader.normal;
            const vec3 leaderHit = glm::mix(eye, mirrored, leaderEyeHeight / span);
            const float margin = ppr::gpu::pprPlaneGridLookupMargin(p, eye, leader.center, mirrored, span);
            ++contained;
            grazing += glm::distance(mirrored, eye) / span > 100.0f;
            ASSERT_TRUE(ppr::gpu::pprPlaneGridRangesMeet(ppr::gpu::pprPlaneGridCellsAround(g, leaderHit, margin), cells))
                << "trial " << trial << " point " << k << ": the lookup missed a reflector that takes the pixel (cells " << cells.x << ".."
                << cells.z << " x " << cells.y << ".." << cells.w << ")";
        }
    }
    EXPECT_GT(contained, 10000) << "the trials should produce many contained hits, edges included";
    EXPECT_GT(grazing, 100) << "and some at grazing angles";
}

// At grazing angles a hit moves far when the plane moves a little: a camera 0.1 mm above a floor,
// a reflector of the same cull plane 10 µm above the leader's. The hit in the leader's plane lies
// cells away from the reflector's own, and only the lookup margin finds the reflector.
TEST(PprPlaneGrid, GrazingHitsFarFromTheLeadersPlaneAreStillLookedUp) {
    const vec3 up(0, 1, 0), east(1, 0, 0), south(0, 0, 1);
    const ReflectorData leader = rectangle(vec3(0), up, east, 1, 1);
    const ReflectorData r = rectangle(vec3(0.05f, ppr::gpu::kPprCullPlaneTolerance, 0), up, east, 0.05f, 0.05f);
    const PprPlaneGrid g = ppr::gpu::pprPlaneGridOver(vec3(-0.4f, 0, -0.4f), vec3(0.4f, 0, 0.4f), east, south);  // 10 cm cells
    const glm::uvec4 cells = ppr::gpu::pprPlaneGridCellsOf(g, r);
    const vec3 eye(-100.0f, 1e-4f, 0.0f);
    int taken = 0, farOff = 0;
    for (int i = 0; i <= 100; ++i)
        for (float height : {2e-3f, 5e-3f, 2e-2f}) {
            // The point at `height` above r whose hit in r's plane is at x along its middle line.
            const float x = -0.05f + 0.2f * float(i) / 100.0f;
            const vec3 onR(x, r.center.y, 0.0f), mirroredEye = eye - 2.0f * (eye.y - r.center.y) * up;
            const vec3 ray = onR - mirroredEye;
            const vec3 p = onR + ray * (height / ray.y);
            const float d = glm::dot(p - r.center, up), eyeHeight = glm::dot(eye - r.center, up);
            const vec3 hit = glm::mix(eye, p - 2.0f * d * up, eyeHeight / (eyeHeight + d));
            if (!ppr::gpu::reflectorContains(r, hit)) continue;
            ++taken;
            const float h = glm::dot(p - leader.center, up), e = glm::dot(eye - leader.center, up), span = h + e;
            const vec3 mirrored = p - 2.0f * h * up, leaderHit = glm::mix(eye, mirrored, e / span);
            farOff += std::abs(leaderHit.x - hit.x) > 0.1f;  // more than a cell away
            const float margin = ppr::gpu::pprPlaneGridLookupMargin(p, eye, leader.center, mirrored, span);
            EXPECT_TRUE(ppr::gpu::pprPlaneGridRangesMeet(ppr::gpu::pprPlaneGridCellsAround(g, leaderHit, margin), cells))
                << "x " << x << " height " << height << ": own hit " << hit.x << ", leader's " << leaderHit.x << ", margin " << margin;
        }
    EXPECT_GT(taken, 100);
    EXPECT_GT(farOff, 10) << "the case should move hits by more than a cell";
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
