// The world-space box of a tile's points that per-tile culling starts from (host/device shared; the
// bound is unit-tested in tests/unit/ppr/tile_box_test.cpp). The reach pass builds it; the projection
// builds the same one when it runs without the reach pass's list.
//
// The projection reconstructs each pixel's position with worldFromDepth: a full product with the
// inverse view-projection and three divisions. The box needs the same points, but not the same
// floats: here a pixel column's and a pixel row's terms of that product are computed once for the
// pixels that share them, the depth term added per pixel, and one reciprocal replaces the divisions
// (on lavapipe, 1920x1080: `ppr.reach` 5.7 -> 5.0 ms). The two then differ by rounding, so the box is
// grown by a bound on that difference (pprPadTileBox) and stays a superset of the projection's
// points: culling never drops a reflector a pixel takes. The bound is a fraction of a millimetre at
// 100 m (it grows with the view distance), under the gap between the culling's height test
// (kPprCullMinHeight, 0.5 mm) and the projection's (kPprAboveEpsilon, 1 mm), so tiles lying in a
// reflector's plane are still culled for it.
#ifndef PPR_TILE_BOX_H
#define PPR_TILE_BOX_H
#include "shader/shared.h"

// Both computations sum the same four products, the projection in some order (γ4 = 4·2^-24 of the
// sum of their magnitudes at most) and this one split five ways (γ5); the slack is twice γ4 + γ5.
PPR_CONST(float, kPprBoxProductSlack, 1.25e-6f)
// A division (2.5 ULP in Vulkan) against a reciprocal (2.5 ULP) and a product: 11·2^-24 of the
// coordinate, twice over. Also covers the rounding of the padding itself.
PPR_CONST(float, kPprBoxQuotientSlack, 1.5e-6f)

PPR_BEGIN
// A pixel column's share of the homogeneous position: column 0 of the inverse view-projection times
// its NDC x, plus half of column 3 (written as a product-and-sum so that every compiler treats it
// the same however many pixels share it: the reach pass and the projection must get the same floats).
PPR_INLINE vec4 pprBoxColumnTerm(mat4 invViewProj, float ndcX) { return invViewProj[0] * ndcX + invViewProj[3] * 0.5f; }
// A pixel row's share: column 1 times its NDC y, plus the other half of column 3.
PPR_INLINE vec4 pprBoxRowTerm(mat4 invViewProj, float ndcY) { return invViewProj[1] * ndcY + invViewProj[3] * 0.5f; }

// The point at `depth` (> 0) under the pixel whose column and row terms are given. The box's growth
// needs the least depth of the tile's points too.
PPR_INLINE vec3 pprBoxPoint(mat4 invViewProj, vec4 columnTerm, vec4 rowTerm, float depth) {
    vec4 h = (columnTerm + rowTerm) + invViewProj[2] * depth;
    return vec3(h.x, h.y, h.z) * (1.0f / h.w);
}

// Grows the box lo..hi of a tile's pprBoxPoint points, whose least depth is leastDepth, so that it
// holds the projection's positions of the same pixels. For a coordinate j with the homogeneous sums
// h (this) and h' (the projection's), |h_j - h'_j| <= (γ4 + γ5) S_j with S_j = |m0j x| + |m1j y| +
// |m2j| depth + |m3j| (|x|, |y| <= 1 on screen), and the quotients differ by at most (|Δh_j| + |p_j|
// |Δh_w|) / |h_w| plus their own rounding. Over the tile 1/|h_w| and depth/|h_w| are at most 1/D and
// leastDepth/D with D = |m2w| leastDepth - (|m0w| + |m1w| + |m3w|) (for a perspective projection the
// sum is nought and D is leastDepth / near). Without such a bound (D <= 0) the box is unbounded.
PPR_INLINE void pprPadTileBox(mat4 invViewProj, float leastDepth, PPR_INOUT(vec3) lo, PPR_INOUT(vec3) hi) {
    vec4 rowSums = abs(invViewProj[0]) + abs(invViewProj[1]) + abs(invViewProj[3]);  // per output coordinate
    vec4 depthTerms = abs(invViewProj[2]);
    float least = depthTerms.w * leastDepth - rowSums.w;  // D
    if (!(least > 0.0f)) {
        lo = vec3(-3.4e38f);
        hi = vec3(3.4e38f);
        return;
    }
    vec2 scale = vec2(1.0f, leastDepth) * (1.01f / least);  // 1 % for the rounding of D
    vec3 magnitude = max(abs(lo), abs(hi));
    vec3 sums = (vec3(rowSums.x, rowSums.y, rowSums.z) + magnitude * rowSums.w) * scale.x +
                (vec3(depthTerms.x, depthTerms.y, depthTerms.z) + magnitude * depthTerms.w) * scale.y;
    vec3 pad = sums * kPprBoxProductSlack + magnitude * kPprBoxQuotientSlack;
    lo -= pad;
    hi += pad;
}
PPR_END

#endif
