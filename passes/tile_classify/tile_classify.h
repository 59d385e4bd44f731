// Tile classification pass constants (host/device shared). Tile size and classes: ppr_common/tiles.h.
#ifndef PPR_TILE_CLASSIFY_H
#define PPR_TILE_CLASSIFY_H
#include "shader/shared.h"

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
