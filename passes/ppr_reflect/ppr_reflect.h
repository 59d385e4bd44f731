// PPR reflection pass constants (host/device shared).
#ifndef PPR_REFLECT_H
#define PPR_REFLECT_H
#include "shader/shared.h"

// Toggles (--set holes / filter / antibleed).
PPR_CONST(uint, kPprHoleFilling, 1u)
PPR_CONST(uint, kPprFiltering, 2u)
PPR_CONST(uint, kPprAntiBleeding, 4u)
// Dispatched over the planar tile list (--set indirect=1) instead of the whole screen.
PPR_CONST(uint, kPprIndirect, 8u)
// --set normalmap=approx|raymarch: the bonus slides' normal-map approximation (reflection pass only).
PPR_CONST(uint, kPprNormalApprox, 16u)
PPR_CONST(uint, kPprNormalRaymarch, 32u)
// --set fallback_env=1: holes show the environment along the reflected ray; hits fade into it at the
// screen edge. With kPprEnvironmentProbe (env_source=probe) it is the reflection probe, else the sky.
PPR_CONST(uint, kPprEnvironment, 64u)
PPR_CONST(uint, kPprEnvironmentProbe, 128u)
// holes=1: the depth-aware hole rule (ppr_resolve.glsl); kPprHoleFilling alone is holes=slides.
PPR_CONST(uint, kPprHoleEnclosed, 256u)
// TAA's reflection history: also write the reflected path length per pixel (outDistance).
PPR_CONST(uint, kPprWriteDistance, 512u)
// --set normal_refine=1: raymarch first tries where the ray crosses the plane (from the depth buffer)
// of the surface the flat reflection sees (normal_map_hit.glsl surfacePlaneHit). With kPprNormalWalk
// (normal_refine=walk, the search before it) it walks and bisects from the taken tap instead
// (walkToCrossing).
PPR_CONST(uint, kPprNormalRefine, 1024u)
PPR_CONST(uint, kPprNormalWalk, 8192u)
// --set contact=1 (with holes=1): a short march from each reflector pixel toward the point its data
// reflects finds what the main view hides between them (an object's underside where it stands on the
// reflector): kPprContactTaps taps, kPprContactFirstTap screen pixels from the pixel and doubling.
PPR_CONST(uint, kPprContactMarch, 2048u)
PPR_CONST(uint, kPprContactTaps, 4u)
PPR_CONST(float, kPprContactFirstTap, 2.0f)
// Bisection steps toward where the ray went behind a surface it lies too far behind at a tap.
PPR_CONST(uint, kPprContactRefineSteps, 3u)
// A tap hits when the ray lies behind the depth buffer by at most this (metres, plus the scale times
// the surface's view distance): ssr-brute's default thickness.
PPR_CONST(float, kPprContactThickness, 0.05f)
PPR_CONST(float, kPprContactThicknessScale, 0.02f)
// How far (texels) the depth-aware rule looks on each side for the enclosing nearer layer.
PPR_CONST(int, kPprHoleReach, 2)
// How far (texels) it looks for the far side of a magnified nearer layer around a texel with data.
PPR_CONST(int, kPprHoleMagnifiedReach, 3)
// holes=1 at a reflector's rim with no data: how close (pixels) a neighbour's mirror image must land,
// and how far in front of the plane it must stand, as a fraction of its view distance.
PPR_CONST(float, kPprRimReach, 3.0f)
PPR_CONST(float, kPprRimMinHeight, 0.002f)
// holes=1, the filtered sample's footprint (ppr_resolve.glsl pprFootprint): a neighbour whose source
// lies this far (pixels) or farther belongs to another layer; above kPprFootprintMinStep source
// pixels per target pixel the sample averages the footprint.
PPR_CONST(float, kPprFootprintMaxStep, 24.0f)
PPR_CONST(float, kPprFootprintMinStep, 1.5f)
// Taps of the normalmap=raymarch march between the pixel and the approximated reflection.
PPR_CONST(uint, kPprNormalTaps, 4u)
// normal_refine=1: how many planes are tried (the one the flat reflection sees, then the
// one shown where the ray crossed it); a crossing is taken where the depth buffer lies within this
// fraction of the view distance of its plane; a plane crossed farther along the ray than this many
// times the flat reflection distance, or met this nearly edge-on (cosine), is not tried.
PPR_CONST(uint, kPprNormalPlaneGuesses, 2u)
PPR_CONST(float, kPprNormalPlaneTolerance, 0.01f)
PPR_CONST(float, kPprNormalPlaneReach, 4.0f)
PPR_CONST(float, kPprNormalPlaneMinFacing, 0.001f)
// normal_refine=walk: bisection steps between a visible point of the ray and the hidden one after it,
// toward where the ray crosses the depth buffer.
PPR_CONST(uint, kPprNormalRefineSteps, 5u)
// normal_refine=walk, where the approximated point is not hidden: up to this many steps on along the
// ray, each this fraction of the taps' spacing, looking for where it falls behind the depth buffer.
PPR_CONST(uint, kPprNormalAheadSteps, 8u)
PPR_CONST(float, kPprNormalAheadStep, 0.25f)
// Hole filling replaces a pixel's own data only when a neighbour's offset is this much shorter
// (pixels; the slides' value).
PPR_CONST(float, kPprHoleMinDistance, 6.0f)

// ppr.reflect lists the planar tiles that hold a pixel ppr.fallback.holes will march (a reflector
// pixel left without a reflection whose mapped normal leaves the plane: ssr_pixel.glsl's test), for
// that pass's indirect dispatch, instead of it visiting every planar tile (indirect=1,
// fallback=ssr_holes, normal maps on). The test here is a little looser than kFlatNormalCos so that
// rounding in one shader cannot leave out a pixel the other marches: a tile too many costs a
// workgroup, never a pixel. (A list of the pixels themselves, marched side by side whatever their
// tile, was slower: 13.3 against 12.2 ms on the normalmap camera, whose holes cluster.)
PPR_CONST(uint, kPprListMappedHoles, 4096u)
PPR_CONST(float, kPprMappedHoleListCos, 0.999995f)

PPR_BEGIN
struct PprReflectPush {
    uint flags;           // kPprHoleFilling | kPprFiltering | kPprAntiBleeding | kPprIndirect
    uint debugView;       // frame.h kDebug*: intermediate, holes and tiles are drawn here
    uint tilesX;          // tiles per row (the per-tile survivor counts of debug=tiles)
    uint maxReflectorId;  // reflector ids above this are beyond PPR's budget: no reflection
};
PPR_END
PPR_SIZE_CHECK(PprReflectPush, 16);

#endif
