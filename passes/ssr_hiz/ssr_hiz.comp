#version 460
#extension GL_GOOGLE_include_directive : require
#define SSR_USES_HIZ 1
#include "ssr_common/ssr_pixel.glsl"
#include "hiz/hiz.h"
#include "hiz/hiz_level0.glsl"
#include "ssr_common/ssr_cells.glsl"

// ssr-hiz: the ray walks the depth hierarchy (hiz/hiz.h) instead of every pixel (Uludag 2014). A cell
// whose nearest surface lies behind the ray cannot be hit anywhere inside, so the ray crosses it in
// one step and tries the next coarser level; where the ray reaches a cell's nearest surface it looks
// one level finer. Only level-0 pixels are tested against the surface, with the same thickness rule
// as ssr-brute. Behind an object the ray walks level-0 pixels; with hiz_skip it crosses an 8x8 cell
// it stays behind in one step where the walk would pass every pixel (hizSkipBehind).
//
// Along the segment the hierarchy's depth d = 1 − near·k is affine in the fraction t, as are the
// pixel coordinates, so both the cell exits and the point where the ray reaches a depth are one
// division each.

// The hierarchy's value of a cell: level 0 is the depth buffer itself (hizLevel0Depth), levels 1.. are in
// the atlas. `depth` gets the level-0 sample, which the surface test then uses without fetching it
// again.
float hizCellMin(int level, ivec2 origin, ivec2 cell, out float depth) {
    depth = 0.0;
    if (level != 0) return imageLoad(hizAtlas, origin + cell).r;
    depth = hizLevel0Depth(depthTex, cell);
    return hizFromReverseZ(depth);
}

// Rounding allowances of hizSkipBehind's tests, which repeat the walk's arithmetic at the ends of
// the cell rather than at each pixel: a compiler may fuse a multiply-add in one place and not in the
// other, so each test keeps this far on the safe side.
const float kHizSkipDepthMargin = 1e-6;     // hierarchy depth (0..1)
const float kHizSkipDistanceMargin = 1e-5;  // relative, view distance

// hiz_skip: the ray has just passed behind the level-0 pixel at cellF (leaving it at tExit) and would
// walk on pixel by pixel. If up to the exit of the 8x8 cell around that pixel (hiz.h kHizFarLevel) it
// stays behind every pixel of the cell, and farther behind each than its surface is thick (the cell's
// farthest surface, the least depth in it, bounds both: the walk's tests are monotone in the depth,
// and the ray's depth and 1/distance are monotone along it, so their worst values are at the ends),
// the walk would cross the rest of the cell without a hit and stop at its exit, at level 0 (the exit
// is the same float either way: both come from the same integer edge). Returns that exit, or tExit
// where the walk could go otherwise: a test fails, or the ray leaves the cell so close to a pixel line
// of the other axis that the walk's nudged lookups (kSsrCrossEps) could leave it a pixel early.
float hizSkipBehind(SsrSegment seg, SsrRay ray, vec2 cellF, float tExit, float d0, float dd, float slack, uvec2 padded) {
    const float farCellSize = float(1u << kHizFarLevel);
    vec2 farCellF = floor(cellF / farCellSize);  // = ssrCellAt(seg, t, farCellSize): exact scaling, same floor
    vec2 exits = ssrCellAxisExits(seg, farCellF, farCellSize);
    float tCell = min(exits.x, exits.y);  // ssrCellExit
    if (!(tCell > tExit)) return tExit;
    ivec2 farCell = clamp(ivec2(farCellF), ivec2(0), ivec2(hizLevelSize(padded, kHizFarLevel)) - 1);
    float farDepth = imageLoad(hizAtlas, hizFarOrigin(padded) + farCell).r;
    // Behind every pixel's surface at every pixel the walk would enter (the walk's "in front" test).
    if (min(d0 + tExit * dd, d0 + tCell * dd) < hizFromReverseZ(farDepth) + kHizSkipDepthMargin) return tExit;
    // Farther behind each than it is thick (the walk's hit test, kOut at most the cell's).
    float dk = ray.k1 - ray.k0;
    float kMax = max(ray.k0 + tExit * dk, ray.k0 + min(tCell + slack, 1.0) * dk);
    float sFar = ssrSurfaceDistanceOf(farDepth);  // sky anywhere in the cell: infinite, no skip
    if (!(1.0 / kMax > (sFar + ssrThicknessAt(sFar)) * (1.0 + kHizSkipDistanceMargin))) return tExit;
    // Where the ray leaves through one axis's edge (b), the other axis (a) must be clear of pixel lines
    // there: not within the lookup nudge of one ahead (or of the cell's edge), nor past one by less
    // than it moves while the b coordinate covers the nudge.
    if (seg.dirSign.x != 0.0 && seg.dirSign.y != 0.0) {
        int b = exits.x <= exits.y ? 0 : 1, a = 1 - b;
        float p = seg.p0[a] + tCell * seg.delta[a];
        float since = seg.dirSign[a] > 0.0 ? p - floor(p) : ceil(p) - p;  // pixels past the last line
        float window = kSsrCrossEps * abs(seg.delta[a] / seg.delta[b]);
        if (since <= window + kSsrCrossEps || 1.0 - since <= 2.0 * kSsrCrossEps) return tExit;
    }
    return tCell;
}

bool ssrTrace(SsrRay ray, out vec2 hitPixel) {
    hitPixel = vec2(0.0);
    SsrSegment seg = ssrSegment(ray);

    float nearPlane = ssrNear();
    float d0 = 1.0 - nearPlane * ray.k0;       // hierarchy depth of the ray at t = 0
    float dd = nearPlane * (ray.k0 - ray.k1);  // its change per unit t; > 0: the ray recedes
    float dk = ray.k1 - ray.k0;
    uvec2 padded = hizPaddedSize(uvec2(frame.screenSize));
    int topLevel = int(min(pc.hizLevels, kHizLevels)) - 1;

    float slack = ssrSlack(seg);
    int level = 0;
    float cellSize = 1.0;
    ivec2 origin = ivec2(0);
    ivec2 levelSize = ivec2(hizLevelSize(padded, 0u));
    // The pixel the ray starts in holds its own surface: leave it before testing anything.
    float t = ssrCellExit(seg, ssrCellAt(seg, 0.0, 1.0), 1.0);

    for (uint i = 0u; i < pc.maxSteps && t < 1.0; ++i) {
        vec2 cellF = ssrCellAt(seg, t, cellSize);
        ivec2 cell = clamp(ivec2(cellF), ivec2(0), levelSize - 1);  // the lookup nudge can reach past the edge
        float depth;
        float cellMin = hizCellMin(level, origin, cell, depth);
        float tExit = ssrCellExit(seg, cellF, cellSize);
        int nextLevel;
        if (d0 + t * dd < cellMin) {
            // In front of everything in the cell. A receding ray may still reach the nearest surface
            // before the far side (give or take the slack); otherwise nothing here can be hit: cross
            // it and try a bigger cell.
            float tReach = dd > 0.0 ? (cellMin - d0) / dd : kSsrNever;
            if (tReach >= tExit + slack) {
                t = tExit;
                nextLevel = min(level + 1, topLevel);
            } else {
                // Back off by the slack so the finer levels still visit the pixel it belongs to
                // (never behind t, which float rounding of tReach could also suggest).
                t = max(t, tReach - slack);
                nextLevel = level - 1;
            }
        } else {
            // Behind the nearest surface in the cell: only finer cells can say where.
            nextLevel = level - 1;
        }
        if (nextLevel >= 0) {
            if (nextLevel != level) {
                level = nextLevel;
                cellSize = float(1u << uint(level));
                origin = hizLevelOrigin(padded, uint(level));
                levelSize = ivec2(hizLevelSize(padded, uint(level)));
            }
            continue;
        }
        // A level-0 pixel whose surface the ray has reached (here or from its entry on). It reflects
        // that surface unless the ray stays further behind it than the surface is thick over the
        // rest of the pixel (and the slack): then the ray passes behind an object and goes on.
        float s = ssrSurfaceDistanceOf(depth);  // the sample hizCellMin fetched
        float kNow = ray.k0 + t * dk, kOut = ray.k0 + min(tExit + slack, 1.0) * dk;
        float nearestRayDistance = 1.0 / max(kNow, kOut);  // 1/k is monotonic along the segment
        if (nearestRayDistance <= s + ssrThicknessAt(s)) {
            hitPixel = vec2(cell) + 0.5;
            return true;
        }
        t = (pc.flags & kSsrHizSkip) != 0u ? hizSkipBehind(seg, ray, cellF, tExit, d0, dd, slack, padded) : tExit;
    }
    return false;
}
