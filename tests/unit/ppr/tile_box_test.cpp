// The tile box of the reach pass (passes/ppr_common/tile_box.h): built from cheaper positions than
// the projection's, then grown. The grown box must hold every position the projection reconstructs
// for the same pixels (worldFromDepth, in whatever order a compiler sums its matrix product), or
// culling could drop a reflector a pixel takes; and it must stay small enough that a tile lying in a
// reflector's plane is still culled for it.
#include "ppr_common/tile_box.h"
#include "ppr_common/tile_culling.h"
#include "scene/camera.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace {

using glm::mat4;
using glm::vec2;
using glm::vec3;
using glm::vec4;

struct Frame {
    vec2 screen{1280.0f, 720.0f}, invScreen{1.0f / 1280.0f, 1.0f / 720.0f};
    mat4 viewProj{1.0f}, invViewProj{1.0f};
};

Frame makeFrame(const ppr::scene::CameraPose& pose, vec2 screen) {
    Frame f;
    f.screen = screen;
    f.invScreen = 1.0f / screen;
    f.viewProj = ppr::scene::projectionMatrix(pose.fovYDeg, screen.x / screen.y, ppr::scene::kNearPlane) * ppr::scene::viewMatrix(pose);
    f.invViewProj = glm::inverse(f.viewProj);
    return f;
}

vec2 ndcOf(const Frame& f, glm::ivec2 pix) { return ((vec2(pix) + 0.5f) * f.invScreen) * 2.0f - 1.0f; }

// worldFromDepth's product summed in three orders a compiler may choose (glm's pairs, left to right,
// fused multiply-adds), each with a division or a reciprocal: the box must hold all of them.
std::vector<vec3> projectionPositions(const Frame& f, glm::ivec2 pix, float depth) {
    const vec2 ndc = ndcOf(f, pix);
    const mat4& m = f.invViewProj;
    const vec4 pairs = m * vec4(ndc, depth, 1.0f);
    const vec4 leftToRight = ((m[0] * ndc.x + m[1] * ndc.y) + m[2] * depth) + m[3];
    vec4 fused;
    for (int j = 0; j < 4; ++j) fused[j] = std::fma(m[3][j], 1.0f, std::fma(m[2][j], depth, std::fma(m[1][j], ndc.y, m[0][j] * ndc.x)));
    std::vector<vec3> out;
    for (const vec4& h : {pairs, leftToRight, fused}) {
        out.push_back(vec3(h) / h.w);
        out.push_back(vec3(h) * (1.0f / h.w));
    }
    return out;
}

struct Box {
    vec3 lo{3.4e38f}, hi{-3.4e38f};
    float leastDepth = 1.0f;
    bool empty() const { return lo.x > hi.x; }
};

// The reach pass's box of a 16x16 tile, quad by quad with shared column and row terms (ppr_reach.comp
// addQuad), grown unless told not to.
Box reachBox(const Frame& f, glm::ivec2 tile, const std::vector<float>& depths, bool grown = true) {
    Box b;
    for (int qy = 0; qy < 16; qy += 2)
        for (int qx = 0; qx < 16; qx += 2) {
            const glm::ivec2 quad = tile * 16 + glm::ivec2(qx, qy);
            const vec2 first = ndcOf(f, quad), second = ndcOf(f, quad + 1);
            const vec4 columns[2] = {ppr::gpu::pprBoxColumnTerm(f.invViewProj, first.x), ppr::gpu::pprBoxColumnTerm(f.invViewProj, second.x)};
            const vec4 rows[2] = {ppr::gpu::pprBoxRowTerm(f.invViewProj, first.y), ppr::gpu::pprBoxRowTerm(f.invViewProj, second.y)};
            for (int c = 0; c < 4; ++c) {
                const int dx = c & 1, dy = c >> 1;
                const float depth = depths[(qy + dy) * 16 + qx + dx];
                if (depth <= 0.0f) continue;
                const vec3 p = ppr::gpu::pprBoxPoint(f.invViewProj, columns[dx], rows[dy], depth);
                b.lo = glm::min(b.lo, p);
                b.hi = glm::max(b.hi, p);
                b.leastDepth = std::min(b.leastDepth, depth);
            }
        }
    if (grown && !b.empty()) ppr::gpu::pprPadTileBox(f.invViewProj, b.leastDepth, b.lo, b.hi);
    return b;
}

bool holds(const Box& b, vec3 p) { return glm::all(glm::lessThanEqual(b.lo, p)) && glm::all(glm::lessThanEqual(p, b.hi)); }

// The reverse-Z depth of the point `distance` metres along the view axis (kNearPlane / w, as a float).
float depthAt(float distance) { return ppr::scene::kNearPlane / distance; }

TEST(TileBox, HoldsEveryPositionTheProjectionReconstructs) {
    std::mt19937 gen(1234);
    auto uni = [&](float a, float b) { return std::uniform_real_distribution<float>(a, b)(gen); };
    const vec2 screens[] = {{1280, 720}, {1920, 1080}, {3840, 2160}, {333, 187}};
    long checked = 0;
    for (int view = 0; view < 300; ++view) {
        ppr::scene::CameraPose pose;
        const float reach = view % 3 == 0 ? 2000.0f : 40.0f;  // some cameras far from the origin
        pose.position = vec3(uni(-reach, reach), uni(-5.0f, reach * 0.25f), uni(-reach, reach));
        pose.yawDeg = uni(-180, 180);
        pose.pitchDeg = uni(-89, 89);
        pose.fovYDeg = uni(20, 100);
        const vec2 screen = screens[view % 4];
        const Frame f = makeFrame(pose, screen);
        for (int t = 0; t < 6; ++t) {
            const glm::ivec2 tile(static_cast<int>(uni(0.0f, screen.x / 16.0f - 1.0f)), static_cast<int>(uni(0.0f, screen.y / 16.0f - 1.0f)));
            // Depths from the near plane to 5 km, log-uniform; some sky; every tile its own spread.
            const float nearest = std::exp(uni(std::log(0.05f), std::log(5000.0f))), spread = std::exp(uni(0.0f, std::log(100.0f)));
            std::vector<float> depths(256);
            for (float& d : depths) d = uni(0.0f, 1.0f) < 0.05f ? 0.0f : depthAt(std::min(nearest * std::exp(uni(0.0f, std::log(spread))), 5000.0f));
            const Box b = reachBox(f, tile, depths);
            for (int k = 0; k < 256; ++k) {
                if (depths[k] <= 0.0f) continue;
                for (const vec3& p : projectionPositions(f, tile * 16 + glm::ivec2(k % 16, k / 16), depths[k])) {
                    ASSERT_TRUE(holds(b, p)) << "view " << view << " tile " << tile.x << "," << tile.y << " pixel " << k << " depth " << depths[k];
                    ++checked;
                }
            }
        }
    }
    EXPECT_GT(checked, 1000000);
}

// A floor tile seen about 100 m away. Tiles lying in a reflector's plane are culled for it while
// their points are under kPprCullMinHeight (0.5 mm) above it; the projection takes only points more
// than 1 mm above. The growth must be a small part of that margin, or far tiles in the plane would
// no longer be culled (nothing would change but the cost). (The positions themselves are off the
// plane by a millimetre or so at this distance: the float inverse of the view-projection.)
TEST(TileBox, GrowsByAFractionOfTheCullingMarginAHundredMetresAway) {
    for (const float eyeHeight : {8.0f, 30.0f}) {
        ppr::scene::CameraPose pose;
        pose.position = vec3(12.0f, eyeHeight, -25.0f);  // off the origin, as in a scene
        pose.pitchDeg = -std::atan(eyeHeight / 100.0f) * 180.0f / 3.14159265f;
        pose.fovYDeg = 60.0f;
        const Frame f = makeFrame(pose, vec2(1920.0f, 1080.0f));
        // The tile at the screen's centre, looking at the floor 100 m ahead; its pixels' depths are
        // the floor's, from the ray through each pixel centre.
        const glm::ivec2 tile(1920 / 32, 1080 / 32);
        std::vector<float> depths(256);
        for (int k = 0; k < 256; ++k) {
            const vec2 ndc = ndcOf(f, tile * 16 + glm::ivec2(k % 16, k / 16));
            const glm::dvec4 nearPoint = glm::dmat4(f.invViewProj) * glm::dvec4(ndc, 1.0, 1.0);
            const glm::dvec3 onNear = glm::dvec3(nearPoint) / nearPoint.w, eye = glm::dvec3(pose.position);
            const double along = eye.y / (eye.y - onNear.y);  // where the ray from the eye through onNear meets y = 0
            const glm::dvec4 clip = glm::dmat4(f.viewProj) * glm::dvec4(eye + (onNear - eye) * along, 1.0);
            depths[k] = static_cast<float>(clip.z / clip.w);
        }
        const Box grown = reachBox(f, tile, depths), points = reachBox(f, tile, depths, false);
        ASSERT_FALSE(points.empty());
        const float farthest = ppr::scene::kNearPlane / points.leastDepth;
        EXPECT_GT(farthest, 95.0f);
        EXPECT_LT(farthest, 120.0f);
        const vec3 growth = glm::max(points.lo - grown.lo, grown.hi - points.hi);
        EXPECT_GT(growth.y, 0.0f);
        EXPECT_LT(growth.y, ppr::gpu::kPprCullMinHeight * 0.4f) << "eye height " << eyeHeight;
        EXPECT_LT(std::max({growth.x, growth.y, growth.z}), 1e-3f) << "eye height " << eyeHeight;
    }
}

TEST(TileBox, AProjectionWithoutABoundLeavesTheBoxUnbounded) {
    vec3 lo(0.0f), hi(1.0f);
    ppr::gpu::pprPadTileBox(mat4(0.0f), 0.5f, lo, hi);  // no depth term in w: no bound on 1/|w|
    EXPECT_LT(lo.x, -1e38f);
    EXPECT_GT(hi.z, 1e38f);
}

}  // namespace
