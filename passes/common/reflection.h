// The reflection image every technique writes (RGBA16F, one per frame) and the composite reads:
// rgb = reflected radiance (linear HDR, unweighted by Fresnel), a = what kind of value it is.
// `ppr compare` reads the same alpha codes back, so they are defined once here.
#ifndef PPR_REFLECTION_H
#define PPR_REFLECTION_H
#include "shader/shared.h"

PPR_CONST(float, kReflectionNone, 0.0f)       // no reflection (not a reflector pixel, or a PPR hole)
PPR_CONST(float, kReflectionHit, 1.0f)        // a reflection; for `planar`: the reflected point is visible in the main view
PPR_CONST(float, kReflectionFilled, 0.75f)    // PPR: taken from a neighbour by hole filling
PPR_CONST(float, kReflectionOffscreen, 0.5f)  // planar: reflected point off screen, occluded in the main view, or sky
// planar: the reflected point lies on another reflector. Its lit colour is a stand-in for a second
// bounce and depends on the viewpoint (a mirror seen from the mirrored camera shows another part of
// the sky), which no single-bounce screen-space technique can reproduce; not scored.
PPR_CONST(float, kReflectionSecondary, 0.25f)
// --set fallback_env=1: a reflection that left the screen or found nothing shows the environment
// (the sky along the reflected ray); covered, but no screen-space hit.
PPR_CONST(float, kReflectionEnvironment, 0.625f)  // exact in RGBA16F, like every code
// --set normalmap (PPR, SSR, the ray-traced reference): a reflector pixel whose normal-mapped normal
// lies within this cosine of the reflector's plane normal is reflected as the flat mirror, so
// reflectors without a normal map look exactly as they do with normalmap=off.
PPR_CONST(float, kFlatNormalCos, 0.99999f)
// Width of the band along the screen border over which a screen-space hit fades into the environment,
// as a fraction of the smaller screen side.
PPR_CONST(float, kEnvironmentEdgeFade, 0.03f)

// Reflected-path images (kReflectedPathFormat, RG32F): every technique writes one under TAA, and the
// planar reference's also feeds compare's error classes. x = length of the reflected path, eye →
// reflector → reflected point (metres; 0 where it is unknown: sky, no reflection). y = an integer tag:
// the reflected point's motion slot (gpu/scene_data.h, 0 = still) shifted by kPathSlotShift, so TAA
// can carry a moving object's reflection back to where it was; its low bits are the planar
// reference's classes (planar/planar.h).
PPR_CONST(uint, kPathSlotShift, 1u)

PPR_BEGIN
PPR_INLINE float pathTag(uint motionSlot, uint classBits) { return float((motionSlot << kPathSlotShift) | classBits); }
PPR_INLINE uint pathMotionSlot(float tag) { return uint(tag) >> kPathSlotShift; }
// Reflectance of a reflective surface that no reflector rectangle covers (curved or rough, shaded by
// a screen-space technique with one mirror ray): a single ray cannot stand for a wide glossy lobe, so
// the mirror image fades as the surface gets rougher.
PPR_INLINE float surfaceReflectance(float roughness) { return (1.0f - roughness) * (1.0f - roughness); }
PPR_END

#endif
