#version 460
#extension GL_GOOGLE_include_directive : require
#define SSR_USES_HIZ 1
#include "ssr_common/ssr_pixel.glsl"
#include "hiz/hiz.h"

// ssr-hiz: the ray walks the depth hierarchy (hiz/hiz.h) instead of every pixel (Uludag 2014). A cell
// whose nearest surface lies behind the ray cannot be hit anywhere inside, so the ray crosses it in
// one step and tries the next coarser level; where the ray reaches a cell's nearest surface it looks
// one level finer. Only level-0 pixels are tested against the surface, with the same thickness rule
// as ssr-brute.
//
// Along the segment the hierarchy's depth d = 1 − near·k is affine in the fraction t, as are the
// pixel coordinates, so both the cell exits and the point where the ray reaches a depth are one
// division each.

// Positions are looked up this far (pixels) ahead along each axis the ray moves on, so a position
// computed at a cell boundary lies in the next cell despite the float error of p0 + t·delta
// (~1e-4 px at these sizes).
const float kHizCrossEps = 1.0 / 64.0;
// Stands for "never" where t is concerned (the segment ends at t = 1).
const float kHizNever = 2.0;
// A depth sample is the surface at its pixel's centre, yet the surface goes on to the pixel's
// edges: the ray counts as reaching a pixel's depth up to this far (pixels along the major axis)
// past the pixel's far side. Without it the staircase of samples lets through rays that graze an
// object's silhouette or run just in front of a receding surface, which do hit the real geometry.
const float kHizSlack = 0.25;

// The ray's screen-space segment: p0 + t·delta, t in [0, 1].
struct HizSegment {
    vec2 p0, delta;
    vec2 dirSign;   // per axis −1 / +1, or 0 where the ray does not move
    vec2 invDelta;  // 1/delta, 0 where the ray does not move
};

// The cell of size `cellSize` (pixels) the ray is in at t, entered in the direction of travel.
vec2 hizCellAt(HizSegment seg, float t, float cellSize) {
    return floor((seg.p0 + t * seg.delta + seg.dirSign * kHizCrossEps) / cellSize);
}

// The fraction t at which the ray leaves a cell through its far side.
float hizCellExit(HizSegment seg, vec2 cell, float cellSize) {
    vec2 far = (cell + max(seg.dirSign, vec2(0.0))) * cellSize;  // the edge ahead on each axis
    vec2 tAxis = (far - seg.p0) * seg.invDelta;
    // An axis the ray does not move along is never crossed.
    return min(seg.dirSign.x != 0.0 ? tAxis.x : kHizNever, seg.dirSign.y != 0.0 ? tAxis.y : kHizNever);
}

bool ssrTrace(SsrRay ray, out vec2 hitPixel) {
    hitPixel = vec2(0.0);
    HizSegment seg;
    seg.p0 = ray.p0;
    seg.delta = ray.p1 - ray.p0;
    // Tiny components count as zero: their exits would lie far beyond the segment anyway, and
    // 1/delta would overflow.
    bvec2 moves = greaterThan(abs(seg.delta), vec2(1e-6));
    seg.dirSign = mix(vec2(0.0), sign(seg.delta), moves);
    seg.invDelta = mix(vec2(0.0), 1.0 / seg.delta, moves);

    float nearPlane = ssrNear();
    float d0 = 1.0 - nearPlane * ray.k0;       // hierarchy depth of the ray at t = 0
    float dd = nearPlane * (ray.k0 - ray.k1);  // its change per unit t; > 0: the ray recedes
    float dk = ray.k1 - ray.k0;
    uvec2 padded = hizPaddedSize(uvec2(frame.screenSize));
    int topLevel = int(min(pc.hizLevels, kHizLevels)) - 1;

    float slack = kHizSlack / max(max(abs(seg.delta.x), abs(seg.delta.y)), 1.0);  // in t
    int level = 0;
    float cellSize = 1.0;
    ivec2 origin = hizLevelOrigin(padded, 0u);
    ivec2 levelSize = ivec2(hizLevelSize(padded, 0u));
    // The pixel the ray starts in holds its own surface: leave it before testing anything.
    float t = hizCellExit(seg, hizCellAt(seg, 0.0, 1.0), 1.0);

    for (uint i = 0u; i < pc.maxSteps && t < 1.0; ++i) {
        vec2 cellF = hizCellAt(seg, t, cellSize);
        ivec2 cell = clamp(ivec2(cellF), ivec2(0), levelSize - 1);  // the lookup nudge can reach past the edge
        float cellMin = imageLoad(hizAtlas, origin + cell).r;
        float tExit = hizCellExit(seg, cellF, cellSize);
        int nextLevel;
        if (d0 + t * dd < cellMin) {
            // In front of everything in the cell. A receding ray may still reach the nearest surface
            // before the far side (give or take the slack); otherwise nothing here can be hit: cross
            // it and try a bigger cell.
            float tReach = dd > 0.0 ? (cellMin - d0) / dd : kHizNever;
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
        float s = ssrSurfaceDistance(cell);
        float kNow = ray.k0 + t * dk, kOut = ray.k0 + min(tExit + slack, 1.0) * dk;
        float nearestRayDistance = 1.0 / max(kNow, kOut);  // 1/k is monotonic along the segment
        if (nearestRayDistance <= s + ssrThicknessAt(s)) {
            hitPixel = vec2(cell) + 0.5;
            return true;
        }
        t = tExit;
    }
    return false;
}
