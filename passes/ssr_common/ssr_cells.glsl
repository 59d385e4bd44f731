// Walking a ray's screen-space segment cell by cell (cells of 1, 2, 4, ... pixels), shared by
// ssr-brute (every pixel) and ssr-hiz (the depth hierarchy's cells). Include after ssr_pixel.glsl.

// Positions are looked up this far (pixels) ahead along each axis the ray moves on, so a position
// computed at a cell boundary lies in the next cell despite the float error of p0 + t·delta
// (~1e-4 px at these sizes).
const float kSsrCrossEps = 1.0 / 64.0;
// Stands for "never" where t is concerned (the segment ends at t = 1).
const float kSsrNever = 2.0;
// A depth sample is the surface at its pixel's centre, yet the surface goes on to the pixel's
// edges: the ray counts as reaching a pixel's depth up to this far (pixels along the major axis)
// past the pixel's far side. Without it the staircase of samples lets through rays that graze an
// object's silhouette or run just in front of a receding surface, which do hit the real geometry.
const float kSsrPixelSlack = 0.25;

// The ray's screen-space segment: p0 + t·delta, t in [0, 1].
struct SsrSegment {
    vec2 p0, delta;
    vec2 dirSign;   // per axis −1 / +1, or 0 where the ray does not move
    vec2 invDelta;  // 1/delta, 0 where the ray does not move
};

// The cell of size `cellSize` (pixels) the ray is in at t, entered in the direction of travel.
vec2 ssrCellAt(SsrSegment seg, float t, float cellSize) {
    return floor((seg.p0 + t * seg.delta + seg.dirSign * kSsrCrossEps) / cellSize);
}

// Per axis, the fraction t at which the ray crosses the cell's edge ahead (kSsrNever on an axis the
// ray does not move along).
vec2 ssrCellAxisExits(SsrSegment seg, vec2 cell, float cellSize) {
    vec2 far = (cell + max(seg.dirSign, vec2(0.0))) * cellSize;  // the edge ahead on each axis
    vec2 tAxis = (far - seg.p0) * seg.invDelta;
    return vec2(seg.dirSign.x != 0.0 ? tAxis.x : kSsrNever, seg.dirSign.y != 0.0 ? tAxis.y : kSsrNever);
}

// The fraction t at which the ray leaves a cell through its far side.
float ssrCellExit(SsrSegment seg, vec2 cell, float cellSize) {
    vec2 exits = ssrCellAxisExits(seg, cell, cellSize);
    return min(exits.x, exits.y);
}

// The fraction of the segment the slack stands for.
float ssrSlack(SsrSegment seg) { return kSsrPixelSlack / max(max(abs(seg.delta.x), abs(seg.delta.y)), 1.0); }

SsrSegment ssrSegment(SsrRay ray) {
    SsrSegment seg;
    seg.p0 = ray.p0;
    seg.delta = ray.p1 - ray.p0;
    // Tiny components count as zero: their exits would lie far beyond the segment anyway, and
    // 1/delta would overflow.
    bvec2 moves = greaterThan(abs(seg.delta), vec2(1e-6));
    seg.dirSign = mix(vec2(0.0), sign(seg.delta), moves);
    seg.invDelta = mix(vec2(0.0), 1.0 / seg.delta, moves);
    return seg;
}
