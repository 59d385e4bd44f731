// Tile classification pass constants (host/device shared). Tile size and classes: ppr_common/tiles.h.
#ifndef PPR_TILE_CLASSIFY_H
#define PPR_TILE_CLASSIFY_H
#include "shader/shared.h"

// Invocations per 16x16 tile workgroup, each classifying (kPprTileSize / 2)^2 / this 2x2 quads (the
// shader's specialization constant; --set classify_threads=auto picks by device type). Lavapipe at
// 1280x720, quads: 16 -> 1.9 ms, 64 -> 3.4, 256 -> 9.8 (pixel by pixel, before: 4 -> 13.2, 8 -> 7.5,
// 16 -> 7.5, 32 -> 9.6, 64 -> 11.5, 256 -> 25.7). H100, pixel by pixel, medians of 2 interleaved runs,
// 1920x1080 / 3840x2160: 16 -> 0.020 / 0.043 ms, 64 -> 0.018 / 0.035, 256 -> 0.018 / 0.041.
PPR_CONST(uint, kTileClassifyThreads, 16u)
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
