// The glass forward pass (host/device shared): transparent surfaces (glTF alphaMode BLEND) drawn over
// the composited opaque scene, back to front, with the depth test against the opaque depth.
#ifndef PPR_GLASS_FORWARD_H
#define PPR_GLASS_FORWARD_H
#include "shader/shared.h"

PPR_BEGIN
// Where a glass panel's reflection lies in the reflection atlas this frame, per reflector index
// (scene order). `valid` = 0: no region (not glass, not visible, or dropped on atlas overflow).
struct GlassRegionData {
    vec2 screenOrigin;  // pixels: top-left of the panel's footprint on screen
    vec2 atlasOrigin;   // texels: top-left of its region in the atlas
    vec2 atlasSize;     // texels
    float scale;        // atlas texels per screen pixel (< 1 when the atlas overflowed)
    uint valid;
};

struct GlassForwardPush {
    uint drawIndex;
    uint flags;  // kGlassReflections
    uint looseGlassCount;  // glass reflectors tested per pixel for a draw bound to none (gbuffer/gbuffer.h)
    uint pad1;
};
PPR_END
PPR_SIZE_CHECK(GlassRegionData, 32);
PPR_SIZE_CHECK(GlassForwardPush, 16);

PPR_CONST(uint, kGlassReflections, 1u)  // --set glass=1: add the panel's reflection from the atlas

PPR_BEGIN
// Atlas texel coordinates of a screen position inside a panel's footprint.
PPR_INLINE vec2 glassAtlasFromScreen(GlassRegionData r, vec2 screen) { return r.atlasOrigin + (screen - r.screenOrigin) * r.scale; }
PPR_END

#endif
