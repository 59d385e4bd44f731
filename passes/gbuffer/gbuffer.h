// G-buffer layout (host/device shared).
#ifndef PPR_GBUFFER_H
#define PPR_GBUFFER_H
#include "shader/shared.h"
// Attachment locations:
//   0 normal    RGBA16F   xyz = world-space shading normal (normal-mapped), w = 1 on geometry
//   1 albedo    RGBA8 sRGB  rgb = base colour
//   2 material  RGBA8     r = roughness, g = metallic, b = 1 if the material is reflective,
//                         a = a moving draw's motion slot / 255 (gpu/scene_data.h MotionData; 0 = still)
//   3 reflector R16_UINT  reflector index + 1 of the surface's reflector rectangle, 0 = none
//   4 emissive  B10G11R11 UFLOAT  rgb = emitted radiance (glTF emissive × KHR_materials_emissive_strength)
//               only when an opaque material emits (GBufferPass::emissive_); else four targets
// Depth: D32, reverse-Z (1 = near, 0 = sky).
PPR_CONST(uint, kGBufferNormal, 0u)
PPR_CONST(uint, kGBufferAlbedo, 1u)
PPR_CONST(uint, kGBufferMaterial, 2u)
PPR_CONST(uint, kGBufferReflector, 3u)
PPR_CONST(uint, kGBufferEmissive, 4u)
// Reflectors no mesh belongs to (e.g. snapped onto the floor in the editor) are found per pixel: a
// surface point within this distance of such a rectangle's plane (metres, plus a fraction of its
// distance to the camera) and inside it takes its id. At most this many are tested.
PPR_CONST(uint, kMaxLooseReflectors, 32u)
// Glass reflectors no glass draw belongs to (one draw holding many panes, as exporters merge a
// building's glazing) are found per pixel by the glass forward pass in the same way, among at most
// this many.
PPR_CONST(uint, kMaxLooseGlassReflectors, 64u)
PPR_CONST(float, kLooseSurfaceTolerance, 0.01f)
PPR_CONST(float, kLooseSurfaceTolerancePerMetre, 0.002f)
#endif
