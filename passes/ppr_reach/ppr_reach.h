// PPR reach pass constants (host/device shared): which screen tiles the projection pass runs on.
#ifndef PPR_REACH_H
#define PPR_REACH_H
#include "shader/shared.h"

// Invocations per workgroup; kPprReachGroupSize / (invocations per tile) tiles each. With many
// reflectors each workgroup first gathers the cull planes' rectangles, a cost per workgroup, so a
// workgroup covers several tiles.
PPR_CONST(uint, kPprReachGroupSize, 64u)
PPR_CONST(uint, kPprReachGroupsPerRow, 1024u)  // workgroups per row of the dispatch; the tiles run on across rows
// Invocations per tile (the shader's specialization constant; --set reach_threads=auto picks by device
// type): one on a CPU device, where invocations are SIMD lanes over neighbouring tiles; on a GPU a
// thread looping over a tile's 256 pixels leaves it idle, so several share the tile. Lavapipe,
// 1280x720, overview, one run: 1 -> 8.6 ms, 4 -> 10.5, 16 -> 13.0, 64 -> 16.1. H100, 1920x1080 /
// 3840x2160, medians of 2 interleaved runs: 1 -> 0.090 / 0.129 ms, 4 -> 0.035 / 0.070,
// 16 -> 0.033 / 0.066, 64 -> 0.041 / 0.109 (docs/performance.md).
PPR_CONST(uint, kPprReachThreads, 1u)
PPR_CONST(uint, kPprReachThreadsGpu, 16u)
// Up to this many reflectors each tile tests every one (the projection's own first test, so exactly
// the tiles with survivors are listed); beyond, each cull plane's merged bounds (PprCullPlaneBounds).
PPR_CONST(uint, kPprReachPerReflector, 64u)

PPR_BEGIN
struct PprReachPush {
    uint reflectorCount;  // reflectors projected (≤ kPprMaxReflectors)
    uint cullPlaneCount;  // ≤ kPprMaxCullPlanes
    uint tilesX;
    uint tilesY;
};
// One entry of the reach pass's list: a tile the projection runs on, with the box of its points
// (order-preserving uints, ppr_common/ordered_float.glsl) that the projection's culling starts from,
// reduced and grown here (ppr_common/tile_box.h) to hold the positions the projection reconstructs,
// so it is not reduced twice.
struct PprReachedTile {
    uvec4 lo;  // xyz: the box's low corner; w: the tile (pprPackTile)
    uvec4 hi;  // xyz: the box's high corner
};
PPR_END
PPR_SIZE_CHECK(PprReachPush, 16);
PPR_SIZE_CHECK(PprReachedTile, 32);

#endif
