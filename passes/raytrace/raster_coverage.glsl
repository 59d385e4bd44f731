// --set rt_coverage=raster (raytrace.h kRaytraceRasterCoverage): a flat mirror pixel's reflection decided
// at silhouettes as the planar reference's rasterizer decides it, so that the two references can be
// told apart by what they compute and not by how they sample (docs/raytraced.md). A rasterizer snaps
// each vertex to 1 / 2^subPixelPrecisionBits of a pixel and tests the pixel centre against those edges;
// a ray tests the exact triangle. Where the centre lies within a snap of an edge the two can differ,
// and a sliver seen edge-on can cover a centre in one and not in the other.
// So: rays through points a few thousandths of a pixel around the centre gather the triangles near it
// (the outer ring first; the inner two only where it met another triangle or the sky); where they do
// not all agree, the one shown is the nearest of them whose snapped, clipped outline (in the mirrored
// view, at the plane raised by kRaytraceClipOffset) covers the centre, with the top-left rule; the sky
// when none does and some ray saw the sky. The screen pass (flat rays, normalmap=off) and the glass
// atlas pass use it. Needs raytrace_common.glsl.
#include "raytrace/raster_coverage.h"

// Rings of 8 rays at 1/512, 1/256 and 1/128 pixel: snapping moves an edge by at most √2 / 2^9 pixel
// with 8 sub-pixel bits, so a ray of some ring crosses any edge that may cover the centre (a sliver
// thinner than a ring's spacing is met by a smaller ring).
const int kCoverageRings = 3, kCoveragePerRing = 8, kCoverageCandidates = 8;
// The i-th ray of ring `ring` (0: the innermost), pixels from the centre; rings are turned half a step apart.
vec2 coverageOffset(int ring, int i) {
    float angle = (float(i) + 0.5 * float(ring)) * (2.0 * 3.14159265 / float(kCoveragePerRing));
    return exp2(-9.0 + float(ring)) * vec2(cos(angle), sin(angle));
}

vec3 mirroredPoint(ReflectorData r, vec3 p) { return p - 2.0 * dot(p - r.center, r.normal) * r.normal; }

// A point's position relative to pixel `pix`'s centre in the mirrored view, in fixed point as the
// rasterizer snaps it; false when it cannot be (behind the eye, or far off the screen).
bool snappedPosition(ReflectorData r, vec3 p, ivec2 pix, float unit, out ivec2 q) {
    vec4 clip = frame.viewProj * vec4(mirroredPoint(r, p), 1.0);
    q = ivec2(0);
    if (clip.w <= 0.0) return false;
    vec2 f = (pixelFromClip(clip) - (vec2(pix) + 0.5)) * unit;
    if (any(greaterThan(abs(f), vec2(1e9)))) return false;  // rasterCoversCentre: within 2^30
    q = ivec2(roundEven(f));
    return true;
}

// Does the triangle, clipped at the plane raised by kRaytraceClipOffset and snapped in the mirrored view,
// cover pixel `pix`'s centre? `known` is false when it cannot be decided that way (a vertex behind the
// mirrored eye): then the ray's own test stands.
bool rasterCovers(HitTriangle h, ReflectorData r, ivec2 pix, float unit, out bool known) {
    known = true;
    vec3 p[3] = vec3[3](h.p0, h.p1, h.p2);
    float s[3];
    for (int i = 0; i < 3; ++i) s[i] = dot(p[i] - r.center, r.normal) - kRaytraceClipOffset;
    // Clipped to s >= 0: at most 4 corners.
    ivec2 q[kRasterMaxCorners];
    int n = 0;
    for (int i = 0; i < 3; ++i) {
        int j = (i + 1) % 3;
        if (s[i] >= 0.0) {
            if (!snappedPosition(r, p[i], pix, unit, q[n])) { known = false; return false; }
            ++n;
        }
        if ((s[i] >= 0.0) != (s[j] >= 0.0)) {
            vec3 c = p[i] + (p[j] - p[i]) * (s[i] / (s[i] - s[j]));
            if (!snappedPosition(r, c, pix, unit, q[n])) { known = false; return false; }
            ++n;
        }
    }
    return rasterCoversCentre(q, n);
}

// The reflection at flat mirror pixel `pix` of reflector r, whose centre's ray is origin + t·dir, as the
// planar reference's rasterizer would show it (see the top of this file); `subpixelBits` from the device.
vec4 rasterCoverageReflection(ReflectorData r, ivec2 pix, vec3 origin, vec3 dir, float eyeDistance, uint subpixelBits) {
    RayHit centre;
    bool centreFound = traceNearest(r, origin, dir, centre);
    RayHit candidates[kCoverageCandidates];
    int count = 0;
    if (centreFound) candidates[count++] = centre;
    bool sawSky = !centreFound, differ = false;
    // The outer ring first, then the inner ones from the innermost out, only where the outer ring left
    // the centre's triangle.
    for (int pass = 0; pass < kCoverageRings && (pass == 0 || differ); ++pass) {
        int ring = (pass + kCoverageRings - 1) % kCoverageRings;
        for (int k = 0; k < kCoveragePerRing; ++k) {
            vec3 d = eyeRayDir(vec2(pix) + 0.5 + coverageOffset(ring, k)), o;
            if (!onPlane(r, d, o)) continue;
            RayHit hit;
            if (!traceNearest(r, o, reflect(d, r.normal), hit)) {
                differ = differ || centreFound;
                sawSky = true;
                continue;
            }
            bool seen = false;
            for (int i = 0; i < count; ++i) seen = seen || (candidates[i].draw == hit.draw && candidates[i].prim == hit.prim);
            if (seen) continue;
            differ = true;
            if (count < kCoverageCandidates) candidates[count++] = hit;
        }
    }
    if (!differ) return reflectionOf(centreFound, centre, r, r.normal, pix, origin, dir, eyeDistance);

    float unit = float(1u << subpixelBits);
    bool found = false;
    RayHit best = centre;
    for (int i = 0; i < count; ++i) {
        HitTriangle h = hitTriangle(candidates[i].draw, candidates[i].prim);
        float t;
        vec3 b;
        if (!rayOnTriangle(h, origin, dir, t, b)) continue;
        bool known;
        bool covers = rasterCovers(h, r, pix, unit, known);
        if (!known) covers = all(greaterThanEqual(b, vec3(0.0))) && t >= clipT(r, origin, dir);
        if (!covers || !passesAlphaMask(candidates[i].draw, candidates[i].prim, b.yz)) continue;
        if (!found || t < best.t) best = RayHit(candidates[i].draw, candidates[i].prim, t, b);
        found = true;
    }
    if (!found && !sawSky) return reflectionOf(centreFound, centre, r, r.normal, pix, origin, dir, eyeDistance);
    return reflectionOf(found, best, r, r.normal, pix, origin, dir, eyeDistance);
}
