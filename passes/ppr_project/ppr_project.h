// PPR projection pass constants (host/device shared).
#ifndef PPR_PROJECT_H
#define PPR_PROJECT_H
#include "shader/shared.h"

// A pixel counts as above a reflector's plane only beyond this (metres, plus a fraction of its
// distance to the camera for depth-reconstruction error), so the reflector surface never reflects itself.
PPR_CONST(float, kPprAboveEpsilon, 1e-3f)
PPR_CONST(float, kPprAboveEpsilonPerMetre, 1e-4f)
// --set facing=1: a surface the mirrored eye sees from behind is hidden in the reflection (by the
// front of the same object), so it is not projected. Below this cosine between its G-buffer normal
// and the direction to the mirrored eye it counts as facing away (a margin for normal maps).
PPR_CONST(float, kPprFacingCos, -0.05f)
// --set splat=1: a surface the reflection magnifies (seen at a grazing angle by the camera, face on by
// the mirrored eye) lands its pixels several pixels apart, and whatever lies behind it shows in the
// gaps. Such a pixel also writes the target pixels between its landing and its right and lower
// neighbours' (the cell of the source grid it starts, mirrored), where those neighbours lie on its
// surface. Only pixels whose estimated stretch (view distances and cosines to the eye and the mirrored
// eye) exceeds kPprSplatMinStretch look at their neighbours; a neighbour is on the surface when its
// G-buffer normal is within kPprSplatNormalCos of the pixel's and it lies within kPprSplatReach pixel
// footprints; a cell whose side lands kPprSplatMaxStep or more pixels away is not filled.
PPR_CONST(float, kPprSplatMinStretch, 1.25f)
PPR_CONST(float, kPprSplatMinCos, 0.02f)  // the cosine to the eye is taken as at least this
PPR_CONST(float, kPprSplatNormalCos, 0.8f)
PPR_CONST(float, kPprSplatReach, 3.0f)
PPR_CONST(float, kPprSplatMaxStep, 16.0f)
// A neighbour not on the surface (the pixel sits on its outline): its ray on the pixel's tangent
// plane, and this fraction of the cell filled on either side (the sample says the surface covers
// the pixel's centre, not how far it reaches; 0.5 overshot, docs/quality.md).
PPR_CONST(float, kPprSplatOutline, 0.25f)

// Invocations per 16x16 tile workgroup, each projecting kPprTileSize^2 / this pixels (the shader's
// specialization constant; --set project_threads=auto picks by device type). On a CPU device the
// culling's barriers cost in proportion to the invocations they stop: lavapipe, ppr.project at
// 1280x720, overview, medians of 3 interleaved runs: 256 -> 91 ms, 128 -> 57, 64 -> 46, 32 -> 31.
// On a GPU more invocations share the culling and the per-pixel work: H100, 1920x1080, medians of
// 2 interleaved runs: 32 -> 0.163 ms, 64 -> 0.133, 128 -> 0.116, 256 -> 0.163. Since the projection
// reads each survivor once per invocation for all its pixels, one pixel each wins there: H200,
// 2026-11-29, 1920x1080 / 3840x2160: 64 -> 0.103 / 0.247 ms, 128 -> 0.076 / 0.204,
// 256 -> 0.066 / 0.182 (docs/performance.md).
PPR_CONST(uint, kPprProjectThreads, 32u)
PPR_CONST(uint, kPprProjectThreadsGpu, 256u)

PPR_BEGIN
struct PprProjectPush {
    uint reflectorCount;  // ≤ kPprMaxReflectors (ppr_common/tiles.h)
    uint cullTiles;       // 1: per-tile reflector culling (--set tiles=1); 0: every reflector per pixel
    uint tilesX;          // tiles per row: index of the per-tile survivor count
    uint cullPlaneCount;  // ≤ kPprMaxCullPlanes (ppr_common/tile_culling.h)
    uint glass;           // 1: glass reflectors write into their atlas regions (--set glass=1); 0: skipped
    uint facingOnly;      // 1: a pixel whose surface faces away from the mirrored eye writes nothing (--set facing=1)
    uint tileList;        // 1: workgroup i projects the tile in the reach pass's list at i (ppr_reach); 0: tile = workgroup id
    uint splat;           // 1: magnified surfaces fill the cells between their pixels' landings (--set splat=1)
};
PPR_END
PPR_SIZE_CHECK(PprProjectPush, 32);

#endif
