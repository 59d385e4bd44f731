// Tile classification pass constants (host/device shared). Tile size and classes: ppr_common/tiles.h.
#ifndef PPR_TILE_CLASSIFY_H
#define PPR_TILE_CLASSIFY_H
#include "shader/shared.h"

PPR_BEGIN
// Invocations per 16x16 tile workgroup, each classifying kPprTileSize^2 / this pixels (measured on
// lavapipe at 1280x720: 4 -> 13.2 ms, 8 -> 7.5, 16 -> 7.5, 32 -> 9.6, 64 -> 11.5, 256 -> 25.7).
PPR_CONST(uint, kTileClassifyThreads, 16u)

struct TileClassifyPush {
    uint tilesX;
    uint tileCount;       // tiles on screen: class c's list starts at c * tileCount
    uint maxReflectorId;  // reflector ids above this (beyond PPR's budget) are not PPR's
    uint pad0;
};
PPR_END
PPR_SIZE_CHECK(TileClassifyPush, 16);

#endif
