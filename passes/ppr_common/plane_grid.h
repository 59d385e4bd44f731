// A small grid over one plane, for the projection pass's point location (host/device shared,
// unit-tested in tests/unit/ppr/plane_grid_test.cpp). When every reflector a tile keeps lies in one
// cull plane (a floor of mirror tiles), every pixel of the tile mirrors to (nearly) the same plane and
// only asks which of them holds its hit point. Scanning all of them made the pass cost 24 times as
// much per pixel at 1 024 tiles as at one. Instead the tile marks, per grid cell, the reflectors whose
// rectangle may reach into it, and a pixel runs the scan's exact per-reflector test over those of the
// cells around its hit only, in the same order: so the chosen reflector, and every image, stay the same.
//
// Conservative by construction: a rectangle's cells are those of its bounding box in the plane
// axes, grown by a slack for float rounding, and cells come from clamp(floor((coord − origin) ·
// scale)), which is monotonic in coord. A point inside the rectangle has coordinates inside the box,
// so its cell is inside the rectangle's cell range, whatever origin and scale are (they only decide
// how well the grid separates reflectors; points beyond the grid fall in its border cells).
#ifndef PPR_PLANE_GRID_H
#define PPR_PLANE_GRID_H
#include "common/reflector_data.h"
#include "ppr_common/tile_culling.h"
#include "shader/shared.h"

PPR_CONST(uint, kPprPlaneGridSize, 8u)  // cells per axis
// A tile uses the grid when its survivors, all in one cull plane, number at least the first and at
// most the second (one bit per survivor per cell: shared memory holds kPprPlaneGridMaxSurvivors / 32
// words per cell).
PPR_CONST(uint, kPprPlaneGridMinSurvivors, 4u)
PPR_CONST(uint, kPprPlaneGridMaxSurvivors, 256u)
PPR_CONST(uint, kPprPlaneGridWords, 8u)  // kPprPlaneGridMaxSurvivors / 32
// World-space slack (metres, plus this fraction of the coordinates' size) of a rectangle's box:
// far more than the rounding between the hit point and the plane.
PPR_CONST(float, kPprPlaneGridSlack, 1e-3f)
PPR_CONST(float, kPprPlaneGridSlackPerMetre, 1e-5f)

PPR_BEGIN
struct PprPlaneGrid {
    vec3 axisU;  // the plane's axes (the cull plane leader's tangent and bitangent)
    vec3 axisV;
    vec2 origin;  // grid corner, in plane coordinates
    vec2 scale;   // cells per metre; 0 on an axis the grid does not split
};

// The grid spanning the box [lo, hi] (the tile's hit region in the plane) along the given axes.
PPR_INLINE PprPlaneGrid pprPlaneGridOver(vec3 lo, vec3 hi, vec3 axisU, vec3 axisV) {
    PprPlaneGrid g;
    g.axisU = axisU;
    g.axisV = axisV;
    vec3 centre = (lo + hi) * 0.5f, halfSize = max((hi - lo) * 0.5f, vec3(0.0f));
    vec2 c = vec2(dot(centre, axisU), dot(centre, axisV));
    vec2 e = vec2(dot(halfSize, abs(axisU)), dot(halfSize, abs(axisV)));
    g.origin = c - e;
    vec2 s = vec2(float(kPprPlaneGridSize)) / (2.0f * e);
    // An empty, huge or non-finite span leaves that axis unsplit (one column): still correct.
    g.scale.x = (e.x > 1e-6f && e.x < 1e6f && s.x > 0.0f && s.x < 1e12f) ? s.x : 0.0f;
    g.scale.y = (e.y > 1e-6f && e.y < 1e6f && s.y > 0.0f && s.y < 1e12f) ? s.y : 0.0f;
    if (g.scale.x == 0.0f) g.origin.x = 0.0f;
    if (g.scale.y == 0.0f) g.origin.y = 0.0f;
    return g;
}

PPR_INLINE uint pprPlaneGridColumn(float coord, float origin, float scale) {
    if (scale == 0.0f) return 0u;
    // clamp before converting: the product may be huge, never NaN (finite coord, origin and scale).
    return uint(clamp(floor((coord - origin) * scale), 0.0f, float(kPprPlaneGridSize - 1u)));
}

// The cell of a point in the plane.
PPR_INLINE uint pprPlaneGridCell(PprPlaneGrid g, vec3 p) {
    return pprPlaneGridColumn(dot(p, g.axisU), g.origin.x, g.scale.x) +
           kPprPlaneGridSize * pprPlaneGridColumn(dot(p, g.axisV), g.origin.y, g.scale.y);
}

// The inclusive cell range (lo x, lo y, hi x, hi y) of the points within `margin` (metres, along each
// axis) of p.
PPR_INLINE uvec4 pprPlaneGridCellsAround(PprPlaneGrid g, vec3 p, float margin) {
    vec2 c = vec2(dot(p, g.axisU), dot(p, g.axisV));
    return uvec4(pprPlaneGridColumn(c.x - margin, g.origin.x, g.scale.x), pprPlaneGridColumn(c.y - margin, g.origin.y, g.scale.y),
                 pprPlaneGridColumn(c.x + margin, g.origin.x, g.scale.x), pprPlaneGridColumn(c.y + margin, g.origin.y, g.scale.y));
}

// How far (metres) from the hit in the plane leader's plane a reflector of the same cull plane may
// see the same pixel's hit in its own: the planes lie up to kPprCullPlaneTolerance apart, plus the
// rounding of the heights, and the hit moves by that times (1 / the cosine of the ray with the
// normal, plus 2). p: the pixel's point; mirrored: its image in the leader's plane; span: the
// heights of p and the eye above that plane, added.
PPR_INLINE float pprPlaneGridLookupMargin(vec3 p, vec3 eye, vec3 leaderCenter, vec3 mirrored, float span) {
    float rounding = 1e-6f * (distance(p, leaderCenter) + distance(eye, leaderCenter));
    return (kPprCullPlaneTolerance + rounding) * (distance(mirrored, eye) / span + 2.0f);
}

// Do two cell ranges share a cell?
PPR_INLINE bool pprPlaneGridRangesMeet(uvec4 a, uvec4 b) { return a.x <= b.z && b.x <= a.z && a.y <= b.w && b.y <= a.w; }

// The inclusive cell range (lo x, lo y, hi x, hi y) that every point reflectorContains accepts falls in.
PPR_INLINE uvec4 pprPlaneGridCellsOf(PprPlaneGrid g, ReflectorData r) {
    vec2 c = vec2(dot(r.center, g.axisU), dot(r.center, g.axisV));
    vec3 size = abs(r.center) + abs(r.tangent) * r.halfExtentU + abs(r.bitangent) * r.halfExtentV;
    float slack = kPprPlaneGridSlack + kPprPlaneGridSlackPerMetre * max(size.x, max(size.y, size.z));
    vec2 e = vec2(abs(dot(r.tangent, g.axisU)) * r.halfExtentU + abs(dot(r.bitangent, g.axisU)) * r.halfExtentV,
                  abs(dot(r.tangent, g.axisV)) * r.halfExtentU + abs(dot(r.bitangent, g.axisV)) * r.halfExtentV) + vec2(slack);
    return uvec4(pprPlaneGridColumn(c.x - e.x, g.origin.x, g.scale.x), pprPlaneGridColumn(c.y - e.y, g.origin.y, g.scale.y),
                 pprPlaneGridColumn(c.x + e.x, g.origin.x, g.scale.x), pprPlaneGridColumn(c.y + e.y, g.origin.y, g.scale.y));
}
PPR_END

#endif
