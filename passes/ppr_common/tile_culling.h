// Per-tile reflector culling for the projection pass (host/device shared, unit-tested against brute
// force in tests/unit/ppr/tile_culling_test.cpp). Every test is conservative: it may keep a
// reflector that reflects nothing in a tile, never drop one that does, so culling on and off give
// bit-identical intermediate buffers.
//
// A pixel p is projected into reflector r when it lies above r's plane, the camera sees r's front,
// the ray from the camera to p's mirror image crosses r's plane inside r's rectangle, and the mirror
// image lands on screen. The written pixel is the screen projection of the mirror image, which is
// also the projection of that crossing point. So it lies both in
//   - the screen rectangle of the tile's mirrored bounding box (per plane: same for coplanar
//     reflectors), and
//   - the screen rectangle of r's rectangle (clipped to the camera's front),
// and a reflector whose rectangles do not overlap there cannot receive a pixel of the tile.
// Screen rectangles are inclusive pixel ranges packed in a uvec2 (x0 | y0 << 16, x1 | y1 << 16),
// grown by kPprCullMarginPx against rounding differences between this and the per-pixel code.
// A third, world-space test is tighter for many small coplanar reflectors (a floor of mirror
// tiles): the crossing point also lies in the tile's hit region (pprTileHitRegion), the plane
// points where rays to the mirror images of the tile's points cross, which must meet the
// reflector's rectangle.
#ifndef PPR_TILE_CULLING_H
#define PPR_TILE_CULLING_H
#include "common/reflector_data.h"
#include "shader/shared.h"

PPR_CONST(float, kPprCullMarginPx, 2.0f)
// Clip-space w below which a point counts as behind the camera (rectangles are clipped there).
PPR_CONST(float, kPprCullMinW, 1e-6f)
PPR_CONST(uint, kPprEmptyRectLo, 0xFFFFFFFFu)  // packed empty rectangle: lo = this, hi = 0
PPR_CONST(uint, kPprEmptyRectHi, 0u)
// A pixel is projected only when it is more than kPprAboveEpsilon (1 mm, ppr_project.h) above the
// plane; tiles whose points are all below half that reflect nothing in it (margin for rounding).
PPR_CONST(float, kPprCullMinHeight, 0.5e-3f)
// World-space slack of the hit-region test (metres): float rounding between it and the per-pixel code.
PPR_CONST(float, kPprCullSlack, 1e-3f)
// Cull planes the projection pass keeps per-tile tables for (shared memory); reflectors in further
// planes get kPprNoCullPlane and are kept or dropped on their own screen rectangle alone.
PPR_CONST(uint, kPprMaxCullPlanes, 256u)
PPR_CONST(uint, kPprNoCullPlane, 0xFFFFu)
// Reflectors share a cull plane when their normals are identical and their centres lie within this
// (metres) of the plane leader's plane (ReflectorBuffer::cullPlanes).
PPR_CONST(float, kPprCullPlaneTolerance, 1e-5f)
// An occluder plane this close to the camera (metres) projects to a sliver that float rounding can
// miss: its screen rectangle is the whole screen.
PPR_CONST(float, kPprNearEyePlane, 1e-3f)

PPR_BEGIN
// Accumulates screen-space bounds of projected points (pixels).
struct PprScreenBounds {
    vec2 lo;
    vec2 hi;
};

PPR_INLINE PprScreenBounds pprEmptyBounds() {
    PprScreenBounds b;
    b.lo = vec2(3.4e38f);
    b.hi = vec2(-3.4e38f);
    return b;
}

// What the per-frame bounds pass (ppr_bounds.comp) stores per reflector.
struct PprReflectorBounds {
    uvec2 rect;     // pprReflectorScreenRect
    uint reflects;  // 1 when the camera may see the reflecting side (it cannot reflect otherwise)
    uint pad0;
};

PPR_INLINE vec2 pprPixelFromClip(vec4 clip, vec2 screenSize) {
    // Clamped far outside the screen first so huge values (points near w = 0) convert safely.
    vec2 ndc = clamp(vec2(clip.x, clip.y) / clip.w, vec2(-4.0f), vec2(4.0f));
    return (ndc * 0.5f + 0.5f) * screenSize;
}

PPR_INLINE void pprAddPoint(PPR_INOUT(PprScreenBounds) b, vec2 pixel) {
    b.lo = min(b.lo, pixel);
    b.hi = max(b.hi, pixel);
}

// Inclusive pixel range on screen after growing by the margin; empty when off screen.
PPR_INLINE uvec2 pprPackBounds(PprScreenBounds b, vec2 screenSize) {
    vec2 lo = b.lo - vec2(kPprCullMarginPx);
    vec2 hi = b.hi + vec2(kPprCullMarginPx);
    if (lo.x > hi.x || lo.y > hi.y || hi.x < 0.0f || hi.y < 0.0f || lo.x >= screenSize.x || lo.y >= screenSize.y)
        return uvec2(kPprEmptyRectLo, kPprEmptyRectHi);
    vec2 maxPixel = screenSize - vec2(1.0f);
    uvec2 l = uvec2(clamp(floor(lo), vec2(0.0f), maxPixel));
    uvec2 h = uvec2(clamp(floor(hi), vec2(0.0f), maxPixel));
    return uvec2(l.x | (l.y << 16u), h.x | (h.y << 16u));
}

PPR_INLINE uvec2 pprFullScreenRect(vec2 screenSize) {
    uvec2 h = uvec2(screenSize) - uvec2(1u);
    return uvec2(0u, h.x | (h.y << 16u));
}

PPR_INLINE bool pprRectsOverlap(uvec2 a, uvec2 b) {
    // Empty rectangles have lo > hi on both axes, so they overlap nothing.
    return (a.x & 0xFFFFu) <= (b.y & 0xFFFFu) && (b.x & 0xFFFFu) <= (a.y & 0xFFFFu) &&
           (a.x >> 16u) <= (b.y >> 16u) && (b.x >> 16u) <= (a.y >> 16u);
}

PPR_INLINE bool pprRectContains(uvec2 r, uvec2 pixel) {
    return pixel.x >= (r.x & 0xFFFFu) && pixel.x <= (r.y & 0xFFFFu) && pixel.y >= (r.x >> 16u) && pixel.y <= (r.y >> 16u);
}

// Screen rectangle of a reflector's rectangle, clipped to w > kPprCullMinW (front of the camera),
// whichever side faces the camera: it bounds where the reflector can receive and occlude.
PPR_INLINE uvec2 pprReflectorScreenRect(ReflectorData r, mat4 viewProj, vec2 screenSize) {
    vec3 u = r.tangent * r.halfExtentU;
    vec3 v = r.bitangent * r.halfExtentV;
    vec4 c0 = viewProj * vec4(r.center - u - v, 1.0f);
    vec4 c1 = viewProj * vec4(r.center + u - v, 1.0f);
    vec4 c2 = viewProj * vec4(r.center + u + v, 1.0f);
    vec4 c3 = viewProj * vec4(r.center - u + v, 1.0f);
    PprScreenBounds b = pprEmptyBounds();
    // Sutherland–Hodgman against one plane, edge by edge around the quad: keep inside corners and
    // add the crossing point of every edge that crosses w = kPprCullMinW.
    for (int e = 0; e < 4; ++e) {
        vec4 a = e == 0 ? c0 : e == 1 ? c1 : e == 2 ? c2 : c3;
        vec4 n = e == 0 ? c1 : e == 1 ? c2 : e == 2 ? c3 : c0;
        bool aIn = a.w > kPprCullMinW;
        bool nIn = n.w > kPprCullMinW;
        if (aIn) pprAddPoint(b, pprPixelFromClip(a, screenSize));
        if (aIn != nIn) {
            float t = (kPprCullMinW - a.w) / (n.w - a.w);
            vec4 x = mix(a, n, t);
            x.w = kPprCullMinW;
            pprAddPoint(b, pprPixelFromClip(x, screenSize));
        }
    }
    return pprPackBounds(b, screenSize);
}

// The bounds pass's entry per reflector: its screen rectangle (the whole screen when its plane
// passes by the camera) and whether the camera may see its reflecting side.
PPR_INLINE PprReflectorBounds pprReflectorBounds(ReflectorData r, mat4 viewProj, vec3 eye, vec2 screenSize) {
    PprReflectorBounds b;
    float eyeHeight = dot(eye - r.center, r.normal);
    b.rect = abs(eyeHeight) < kPprNearEyePlane ? pprFullScreenRect(screenSize) : pprReflectorScreenRect(r, viewProj, screenSize);
    // The projection pass skips a reflector when eyeHeight <= 0; the tolerance keeps this conservative.
    b.reflects = eyeHeight > -1e-5f ? 1u : 0u;
    b.pad0 = 0u;
    return b;
}

// Screen rectangle where the mirror images (in the plane through planePoint with unit planeNormal)
// of the tile's points above that plane can land; the tile's points lie in the box lo..hi. Empty
// when no point of the box is above the plane; the whole screen when a mirrored corner is behind
// the camera (the box's image then has no finite screen bounds).
PPR_INLINE uvec2 pprTileReflectedRect(vec3 lo, vec3 hi, vec3 planeNormal, vec3 planePoint, mat4 viewProj, vec2 screenSize) {
    vec3 centre = (lo + hi) * 0.5f;
    vec3 halfSize = (hi - lo) * 0.5f;
    float highest = dot(centre - planePoint, planeNormal) + dot(halfSize, abs(planeNormal));
    if (highest <= kPprCullMinHeight) return uvec2(kPprEmptyRectLo, kPprEmptyRectHi);
    PprScreenBounds b = pprEmptyBounds();
    for (int k = 0; k < 8; ++k) {
        vec3 corner = vec3((k & 1) != 0 ? hi.x : lo.x, (k & 2) != 0 ? hi.y : lo.y, (k & 4) != 0 ? hi.z : lo.z);
        vec3 mirrored = corner - 2.0f * dot(corner - planePoint, planeNormal) * planeNormal;
        vec4 clip = viewProj * vec4(mirrored, 1.0f);
        if (clip.w <= kPprCullMinW) return pprFullScreenRect(screenSize);
        pprAddPoint(b, pprPixelFromClip(clip, screenSize));
    }
    return pprPackBounds(b, screenSize);
}
// World-space box of the tile's hit region in the plane (through planePoint, unit planeNormal): where
// the rays from `eye` to the mirror images of the box's points higher than kPprCullMinHeight cross
// the plane. That ray crosses where the ray from the mirrored eye to the point itself does, so the
// region is the box, clipped to that height, projected from the mirrored eye: the hull of its
// projected vertices (corners above, and where edges cross the height). Empty (lo > hi) when no
// point is that high; unbounded when the camera is not in front of the plane.
PPR_INLINE void pprTileHitRegion(vec3 lo, vec3 hi, vec3 planeNormal, vec3 planePoint, vec3 eye, PPR_OUT(vec3) hitLo, PPR_OUT(vec3) hitHi) {
    hitLo = vec3(3.4e38f);
    hitHi = vec3(-3.4e38f);
    float eyeHeight = dot(eye - planePoint, planeNormal);
    if (eyeHeight <= 1e-4f) {
        hitLo = vec3(-3.4e38f);
        hitHi = vec3(3.4e38f);
        return;
    }
    vec3 mirroredEye = eye - 2.0f * eyeHeight * planeNormal;
    for (int k = 0; k < 8; ++k) {
        vec3 corner = vec3((k & 1) != 0 ? hi.x : lo.x, (k & 2) != 0 ? hi.y : lo.y, (k & 4) != 0 ? hi.z : lo.z);
        float d = dot(corner - planePoint, planeNormal);
        if (d >= kPprCullMinHeight) {
            vec3 hit = mix(mirroredEye, corner, eyeHeight / (eyeHeight + d));
            hitLo = min(hitLo, hit);
            hitHi = max(hitHi, hit);
        }
        for (int axis = 0; axis < 3; ++axis) {  // the edges from this corner towards +x, +y, +z
            int bit = 1 << axis;
            if ((k & bit) != 0) continue;
            int m = k | bit;
            vec3 other = vec3((m & 1) != 0 ? hi.x : lo.x, (m & 2) != 0 ? hi.y : lo.y, (m & 4) != 0 ? hi.z : lo.z);
            float e = dot(other - planePoint, planeNormal);
            if ((d < kPprCullMinHeight) != (e < kPprCullMinHeight)) {
                vec3 crossing = mix(corner, other, (kPprCullMinHeight - d) / (e - d));
                vec3 hit = mix(mirroredEye, crossing, eyeHeight / (eyeHeight + kPprCullMinHeight));
                hitLo = min(hitLo, hit);
                hitHi = max(hitHi, hit);
            }
        }
    }
    hitLo -= vec3(kPprCullSlack);
    hitHi += vec3(kPprCullSlack);
}

// Does the reflector's rectangle meet the world-space box lo..hi?
PPR_INLINE bool pprRectangleMeetsBox(ReflectorData r, vec3 lo, vec3 hi) {
    vec3 extent = abs(r.tangent) * r.halfExtentU + abs(r.bitangent) * r.halfExtentV;  // as pprRectangleBox
    return all(lessThanEqual(r.center - extent, hi)) && all(lessThanEqual(lo, r.center + extent));
}

// The culling's per-reflector verdict for a tile (the projection's survivor list, the reach pass's
// tile list): the camera may see the reflecting side, the tile mirrored in the reflector's cull plane
// lands on its screen rectangle (`mirrored`: pprTileReflectedRect) and the tile's hit region in that
// plane (pprTileHitRegion) meets the rectangle. A reflector beyond the plane tables
// (kPprNoCullPlane; `mirrored` and the hit region are then not read) is kept wherever its own
// rectangle is on screen.
// In two halves, for a caller that builds the hit region only when the first passes (the reach
// pass): the screen-rectangle half rules the reflector out (false) or leaves the verdict to
// pprRectangleMeetsBox on the hit region for a reflector in a cull plane (one beyond the tables is
// then kept).
PPR_INLINE bool pprTileMayReachReflectorOnScreen(ReflectorData r, PprReflectorBounds b, uvec2 mirrored) {
    if (b.reflects == 0u) return false;
    if (r.cullPlane == kPprNoCullPlane) return pprRectsOverlap(b.rect, b.rect);
    return pprRectsOverlap(mirrored, b.rect);
}
PPR_INLINE bool pprTileMayReachReflector(ReflectorData r, PprReflectorBounds b, uvec2 mirrored, vec3 hitLo, vec3 hitHi) {
    return pprTileMayReachReflectorOnScreen(r, b, mirrored) && (r.cullPlane == kPprNoCullPlane || pprRectangleMeetsBox(r, hitLo, hitHi));
}
PPR_END
PPR_SIZE_CHECK(PprReflectorBounds, 16);

PPR_BEGIN
// The frame's reflectors compacted by the bounds pass, ahead of a uint list in the same buffer
// ("ppr.visible_reflectors"): entries [0, reflecting) are the reflectors on screen whose reflecting
// side the camera may see, in projection order (the projection's survivor candidates); entries
// [reflectorCount, reflectorCount + onScreen) those on screen either side facing (its possible
// occluders). A reflector missing from a list fails the culling tests that read it anyway
// (pprTileMayReachReflector, pprRectsOverlap on an empty rectangle), so the lists change no image.
struct PprVisibleCounts {
    uint reflecting;
    uint onScreen;
    uint untabled;  // reflecting reflectors beyond the cull-plane tables (kPprNoCullPlane)
    uint pad0;
};
PPR_END
PPR_SIZE_CHECK(PprVisibleCounts, 16);

// Candidates per culling chunk: the bounds pass summarises each run of kPprCullChunk consecutive
// candidates (ranks 8c .. 8c + 7 of the reflecting list), and a tile that the summary rules out
// skips the run's reflectors without reading them; likewise each run of the on-screen list, where a
// tile gathers its possible occluders.
PPR_CONST(uint, kPprCullChunk, 8u)
PPR_CONST(uint, kPprCullChunkCount, 128u)  // kPprMaxReflectors / kPprCullChunk

PPR_BEGIN
// A chunk's summary: the union of its reflectors' screen rectangles, the union of their world boxes
// (pprRectangleMeetsBox's, grown by kPprCullSlack against rounding between the shaders that compute
// them; candidates' chunks only), their cull plane when they share one (else kPprNoCullPlane) and
// whether all of them are glass (on-screen chunks only).
struct PprCullChunk {
    uvec2 rect;
    vec3 boxLo;
    uint cullPlane;
    vec3 boxHi;
    uint allGlass;
};
PPR_END
PPR_SIZE_CHECK(PprCullChunk, 40);

PPR_BEGIN
// Per cull plane, reduced by the bounds pass over the plane's reflectors in the reflecting list: the
// union of their screen rectangles and of their world boxes (pprRectangleBox grown by kPprCullSlack,
// as the chunk summaries), which the reach pass tests a tile against beyond kPprReachPerReflector
// reflectors. No reflector of the plane listed: loX > hiX.
struct PprCullPlaneBounds {
    uint loX;
    uint loY;
    uint hiX;
    uint hiY;
    uvec3 boxLo;  // order-preserving uints (ppr_common/ordered_float.glsl)
    uint pad0;
    uvec3 boxHi;
    uint pad1;
};
PPR_END
PPR_SIZE_CHECK(PprCullPlaneBounds, 48);

// "ppr.visible_reflectors" as the shaders declare it (`buffer Visible { PPR_VISIBLE_REFLECTORS; }`):
// the counts, the candidates' chunk summaries, the on-screen list's, the cull planes' bounds, then the
// two lists.
#ifndef __cplusplus
#define PPR_VISIBLE_REFLECTORS                                                      \
    PprVisibleCounts visibleCounts;                                                 \
    PprCullChunk cullChunks[2u * kPprCullChunkCount];                               \
    PprCullPlaneBounds cullPlaneBounds[kPprMaxCullPlanes];                          \
    uint visibleLists[]
#endif
PPR_CONST(uint, kPprVisibleListsOffset, 16u + 40u * 2u * kPprCullChunkCount + 48u * kPprMaxCullPlanes)  // bytes before visibleLists

PPR_BEGIN
// The world box pprRectangleMeetsBox tests a reflector's rectangle by.
PPR_INLINE void pprRectangleBox(ReflectorData r, PPR_OUT(vec3) lo, PPR_OUT(vec3) hi) {
    vec3 extent = abs(r.tangent) * r.halfExtentU + abs(r.bitangent) * r.halfExtentV;
    lo = r.center - extent;
    hi = r.center + extent;
}

// May any reflector of the chunk pass pprTileMayReachReflector for the tile? Conservative: a
// reflector that passes shares the chunk's plane (so `mirrored` and the hit region are its plane's),
// its rectangle lies in the chunk's and its box in the chunk's box. Chunks mixing planes, or
// holding reflectors beyond the plane tables, are never ruled out.
PPR_INLINE bool pprTileMayReachChunk(PprCullChunk c, uvec2 mirrored, vec3 hitLo, vec3 hitHi) {
    if (c.cullPlane == kPprNoCullPlane) return true;
    return pprRectsOverlap(mirrored, c.rect) && all(lessThanEqual(c.boxLo, hitHi)) && all(lessThanEqual(hitLo, c.boxHi));
}
PPR_END

#endif
