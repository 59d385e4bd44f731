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
#ifndef PPR_TILE_CULLING_H
#define PPR_TILE_CULLING_H
#include "common/reflector_data.h"
#include "shader/shared.h"

PPR_CONST(float, kPprCullMarginPx, 2.0f)
// Clip-space w below which a point counts as behind the camera (rectangles are clipped there).
PPR_CONST(float, kPprCullMinW, 1e-6f)
PPR_CONST(uint, kPprEmptyRectLo, 0xFFFFFFFFu)  // packed empty rectangle: lo = this, hi = 0
PPR_CONST(uint, kPprEmptyRectHi, 0u)

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

// Screen rectangle where the mirror images (in the plane through planePoint with unit planeNormal)
// of the tile's points above that plane can land; the tile's points lie in the box lo..hi. Empty
// when no point of the box is above the plane; the whole screen when a mirrored corner is behind
// the camera (the box's image then has no finite screen bounds).
PPR_INLINE uvec2 pprTileReflectedRect(vec3 lo, vec3 hi, vec3 planeNormal, vec3 planePoint, mat4 viewProj, vec2 screenSize) {
    vec3 centre = (lo + hi) * 0.5f;
    vec3 halfSize = (hi - lo) * 0.5f;
    float highest = dot(centre - planePoint, planeNormal) + dot(halfSize, abs(planeNormal));
    if (highest <= 0.0f) return uvec2(kPprEmptyRectLo, kPprEmptyRectHi);
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
PPR_END
PPR_SIZE_CHECK(PprReflectorBounds, 16);

#endif
