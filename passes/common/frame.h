// Per-frame constants shared by every pass (one uniform buffer per frame in flight).
#ifndef PPR_FRAME_H
#define PPR_FRAME_H
#include "shader/shared.h"

PPR_BEGIN
struct FrameConstants {
    mat4 view;
    mat4 proj;
    mat4 viewProj;
    mat4 invViewProj;
    mat4 lightViewProj;     // shadow map projection (reverse-Z orthographic)
    vec4 cameraPos;         // xyz, w = near plane
    vec4 lightDir;          // xyz: direction the light travels (unit), w = shadow map texel size (1/res)
    vec4 lightColor;        // rgb radiance, w = exposure
    vec4 skyColor;          // rgb ambient from above, w = ambient strength
    vec4 groundColor;       // rgb ambient from below
    vec2 screenSize;        // pixels
    vec2 invScreenSize;
    uint frameIndex;
    uint debugView;         // DebugView value (composite)
    uint mirrored;          // 1 in a mirrored view: the reflection flips triangle winding
    uint pad1;
    mat4 prevViewProj;      // the previous frame's main view-projection without jitter (TAA's motion)
    vec4 jitter;            // xy: this frame's sub-pixel jitter in NDC (proj = shift(jitter) × unjittered), zw: 0
};
PPR_END
PPR_SIZE_CHECK(FrameConstants, 6 * 64 + 6 * 16 + 16 + 16);

// Debug views selectable with --set debug=... (names and help: app/settings/debug_views.cpp)
PPR_CONST(uint, kDebugNone, 0u)
PPR_CONST(uint, kDebugAlbedo, 1u)
PPR_CONST(uint, kDebugNormals, 2u)
PPR_CONST(uint, kDebugRoughness, 3u)
PPR_CONST(uint, kDebugReflectors, 4u)
PPR_CONST(uint, kDebugDepth, 5u)
PPR_CONST(uint, kDebugShadow, 6u)
PPR_CONST(uint, kDebugIntermediate, 7u)  // PPR: the decoded intermediate buffer
PPR_CONST(uint, kDebugHoles, 8u)         // PPR: own data / hole-filled / no data per reflector pixel
PPR_CONST(uint, kDebugTiles, 9u)         // PPR: reflectors surviving per-tile culling, as a heat map
PPR_CONST(uint, kDebugAtlas, 10u)        // PPR: the glass reflection atlas, fitted to the screen height
PPR_CONST(uint, kDebugMotion, 11u)       // TAA's motion to last frame (pixels; black = still)
PPR_CONST(uint, kDebugViewCount, 12u)    // app/settings/debug_views.cpp names each of them once
PPR_CONST(float, kDebugMotionRange, 4.0f)  // motion debug view: pixels of motion shown at full brightness

#endif
