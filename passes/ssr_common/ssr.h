// Screen-space ray marching shared by the four SSR techniques (ssr_brute, ssr_lowq, ssr_hiz,
// ssr_linear) and PPR's fallback on non-planar tiles (host/device shared).
//
// Every technique marches the same ray, set up once in ssr_common/ssr_pixel.glsl: from the surface
// point along the view ray mirrored about the surface normal (the reflector's plane normal on
// reflector pixels, so the techniques are judged on the same mirror as PPR and the planar ground
// truth; the G-buffer normal elsewhere), for at most `maxDistance` metres, clipped at the near plane.
// Along the ray's screen-space segment 1/w is affine, and w is the view distance, so every technique
// interpolates k = 1/distance and needs no matrix work per step (McGuire & Mara 2014).
#ifndef PPR_SSR_H
#define PPR_SSR_H
#include "shader/shared.h"

// Flags (SsrPush::flags).
PPR_CONST(uint, kSsrIndirect, 1u)     // dispatched over tile list `listClass` (ppr_common/tiles.h)
PPR_CONST(uint, kSsrWriteAll, 2u)     // whole-screen dispatch into a fresh image: write every pixel
PPR_CONST(uint, kSsrMappedNormals, 4u)  // reflector pixels reflect about the normal-mapped normal (--set normalmap)
PPR_CONST(uint, kSsrEnvironment, 8u)    // misses show the environment, hits fade into it at the border (--set fallback_env)
PPR_CONST(uint, kSsrEnvironmentProbe, 16u)  // ... and the environment is the reflection probe (env_source=probe), else the sky
PPR_CONST(uint, kSsrWriteDistance, 32u)  // write each shaded pixel's reflected path length, eye → surface → hit (0 = none; TAA)
// Reflector pixels are shaded only where the reflection image holds none yet (kReflectionNone, or the
// environment standing in for one) and the mapped normal leaves the plane: PPR's holes on
// normal-mapped reflectors (--set fallback=ssr_holes).
PPR_CONST(uint, kSsrHolesOnly, 64u)
// ssr-hiz (and PPR's fallback): behind an object, cross an 8x8 cell whose farthest surface the ray
// stays behind in one step instead of pixel by pixel (hiz/hiz.h kHizFarLevel; --set hiz_skip).
PPR_CONST(uint, kSsrHizSkip, 128u)
// Pixel classes shaded (SsrPush::pixelClasses): bit kTileClassPlanar = reflector-rectangle pixels,
// bit kTileClassOther = reflective pixels no rectangle covers (rough or curved surfaces).

// ssr-lowq: pixels between samples, and the binary-search steps that refine the last segment
// (log2 of the stride: the search ends at pixel precision).
PPR_CONST(float, kSsrLowqStride, 64.0f)
PPR_CONST(uint, kSsrLowqRefineSteps, 6u)
// ssr-linear: pixels per step when the step count follows the segment's length on screen, and the
// binary-search steps after a hit (as in the write-up: 5).
PPR_CONST(float, kSsrLinearPixelsPerStep, 4.0f)
PPR_CONST(uint, kSsrLinearRefineSteps, 5u)

PPR_BEGIN
// The parameter block every technique shares (--set ssr_distance / ssr_thickness /
// ssr_thickness_scale / ssr_steps), plus what the dispatch needs.
struct SsrPush {
    float maxDistance;     // metres along the reflected ray
    float thickness;       // metres: a sample hits when the ray lies behind the surface by at most
    float thicknessScale;  //   thickness + thicknessScale × the surface's view distance
    uint maxSteps;         // cap on march iterations per ray (samples, or hierarchy steps for ssr-hiz)
    uint flags;            // kSsr*
    uint pixelClasses;     // bit mask of tile classes whose pixels are shaded
    uint listClass;        // the tile list read when kSsrIndirect
    uint tileCount;        // tiles per list (list c starts at c × tileCount)
    uint hizLevels;        // ssr-hiz: levels in the depth hierarchy (hiz/hiz.h)
    uint pad0, pad1, pad2;
};
PPR_END
PPR_SIZE_CHECK(SsrPush, 48);

PPR_BEGIN
// A sample hits when the ray's view distance lies behind the surface's by at most the thickness.
PPR_INLINE float ssrThickness(float surfaceDistance, float thickness, float thicknessScale) {
    return thickness + thicknessScale * surfaceDistance;
}
PPR_END

#endif
