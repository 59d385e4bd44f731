// Tile classification pass constants (host/device shared). Tile size and classes: ppr_common/tiles.h.
#ifndef PPR_TILE_CLASSIFY_H
#define PPR_TILE_CLASSIFY_H
#include "shader/shared.h"

// Invocations per workgroup; kTileClassifyGroupSize / (invocations per tile) tiles each.
PPR_CONST(uint, kTileClassifyGroupSize, 64u)
PPR_CONST(uint, kTileClassifyGroupsPerRow, 1024u)  // workgroups per row of the dispatch; the tiles run on across rows
// Invocations per 16x16 tile, each classifying (kPprTileSize / 2)^2 / this 2x2 quads (the shader's
// specialization constant; --set classify_threads=auto picks by device type). On a CPU device one
// per tile: lavapipe, 1920x1080, medians of 3 interleaved runs: 1 -> 2.40 ms, 16 -> 4.63 (one
// workgroup per tile before: 16 -> 4.62; at 1280x720 16 -> 1.9 ms, 64 -> 3.4, 256 -> 9.8). H100, pixel by
// pixel, one workgroup per tile, medians of 2 interleaved runs, 1920x1080 / 3840x2160: 16 -> 0.020 /
// 0.043 ms, 64 -> 0.018 / 0.035, 256 -> 0.018 / 0.041.
PPR_CONST(uint, kTileClassifyThreads, 1u)
PPR_CONST(uint, kTileClassifyThreadsGpu, 64u)

PPR_BEGIN
struct TileClassifyPush {
    uint tilesX;
    uint tileCount;       // tiles on screen: class c's list starts at c * tileCount
    uint maxReflectorId;  // reflector ids above this (beyond PPR's budget) are not PPR's
    uint pad0;
};
PPR_END
PPR_SIZE_CHECK(TileClassifyPush, 16);

#endif
