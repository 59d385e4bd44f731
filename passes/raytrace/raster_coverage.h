// The rasterizer's coverage decision for one pixel centre (host/device shared; unit-tested in
// tests/unit/raytrace/raster_coverage_test.cpp): the ray-traced reference's rt_coverage=raster
// (raster_coverage.glsl) tests a candidate triangle as the planar reference's rasterizer does, on its
// corners snapped to the device's sub-pixel grid, in fixed point relative to the pixel centre.
#ifndef PPR_RASTER_COVERAGE_H
#define PPR_RASTER_COVERAGE_H
#include "shader/shared.h"

// The most corners a triangle has once clipped by one plane.
PPR_CONST(int, kRasterMaxCorners, 4)

PPR_BEGIN
// Sign (−1, 0, 1) of a.x·b.y − a.y·b.x, exactly: the products are 64-bit (snapped coordinates of a
// large triangle overflow a float's 24 bits long before an int's 31).
PPR_INLINE int rasterCrossSign(ivec2 a, ivec2 b) {
    int hi1, lo1, hi2, lo2;
    imulExtended(a.x, b.y, hi1, lo1);
    imulExtended(a.y, b.x, hi2, lo2);
    if (hi1 != hi2) return hi1 > hi2 ? 1 : -1;
    if (lo1 == lo2) return 0;
    return uint(lo1) > uint(lo2) ? 1 : -1;
}

// Which way the convex outline with corners q[0..n) turns: the first turn that is not straight (all
// turn the same way in a convex outline; exact, since corner differences fit an int when the corners
// lie within 2^30 of the centre). 0: degenerate.
PPR_INLINE int rasterOrientation(ivec2 q[kRasterMaxCorners], int n) {
    int orient = 0;
    for (int i = 0; i < n && orient == 0; ++i) orient = rasterCrossSign(q[(i + 1) % n] - q[i], q[(i + 2) % n] - q[i]);
    return orient;
}

// Does the convex outline with corners q[0..n) (fixed point, the pixel centre at the origin, y down)
// cover the centre? An edge's function at the origin is cross(a, b); a centre on an edge counts only
// for a top edge (horizontal, the inside below) or a left edge (the inside to its right), so of two
// outlines sharing an edge exactly one covers a centre on it. A degenerate outline covers nothing.
// The corners must lie within 2^30 of the centre.
PPR_INLINE bool rasterCoversCentre(ivec2 q[kRasterMaxCorners], int n) {
    if (n < 3) return false;
    int orient = rasterOrientation(q, n);
    if (orient == 0) return false;
    for (int i = 0; i < n; ++i) {
        ivec2 a = q[i], b = q[(i + 1) % n];
        int e = rasterCrossSign(a, b) * orient;
        if (e < 0) return false;
        if (e == 0) {
            ivec2 d = (b - a) * orient;  // the edge turned so that the inside lies on its left
            if (!((d.y == 0 && d.x > 0) || d.y < 0)) return false;
        }
    }
    return true;
}
PPR_END

#endif
