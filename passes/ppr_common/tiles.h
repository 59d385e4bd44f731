// Screen tiles shared by tile classification, the projection pass's reflector culling and the
// indirectly dispatched reflection pass (host/device shared).
#ifndef PPR_TILES_H
#define PPR_TILES_H
#include "shader/shared.h"

// 16x16: one workgroup of 256 threads per tile. Per-tile culling is paid per tile, so larger tiles
// amortise it, and its shared-memory lists fit in about 12 KB (8x8 has not been measured yet).
PPR_CONST(uint, kPprTileSize, 16u)
// Reflectors PPR handles at once; the rest of a larger set are ignored with a warning. Bounded by
// the projection pass's shared-memory tables (ppr_project.comp).
PPR_CONST(uint, kPprMaxReflectors, 1024u)

// Tile classes, one list each.
PPR_CONST(uint, kTileClassPlanar, 0u)  // holds pixels of a reflector rectangle (PPR)
PPR_CONST(uint, kTileClassOther, 1u)   // reflective pixels no rectangle covers (screen-space fallback)
PPR_CONST(uint, kTileClassCount, 2u)

PPR_BEGIN
// The dispatch arguments of the tile lists: one VkDispatchIndirectCommand per class, x = tiles in
// the list (appended atomically by the classification), y = z = 1.
struct TileDispatchArgs {
    uint x;
    uint y;
    uint z;
};
PPR_END
PPR_SIZE_CHECK(TileDispatchArgs, 12);

PPR_BEGIN
// Per-frame counters read back by the host (report.json, the viewer, the tests).
struct PprFrameStats {
    TileDispatchArgs dispatch[2];  // copy of the classification's arguments, per class (x = tiles)
    uint tilesWithContent;         // tiles with geometry (the projection pass's work)
    uint reflectorTilePairs;       // (tile, reflector) pairs that survived culling
    uint occluderTilePairs;        // (tile, reflector) pairs kept as possible occluders
    uint maxTileSurvivors;         // the most reflectors surviving in one tile
    uint tilesProjected;           // workgroups of the projection pass (all tiles, or the reach pass's list)
    uint tilesWithSurvivors;       // tiles left with at least one reflector after culling
    uint reflectorsReflecting;     // reflectors on screen showing their reflecting side (ppr.bounds's list)
    uint reflectorsOnScreen;       // reflectors on screen, either side (possible occluders)
    uint tilesOnPlaneGrid;         // tiles whose pixels found their reflector in a plane grid (ppr_common/plane_grid.h)
    uint tilesWithMappedHoles;     // planar tiles ppr.fallback.holes marches (ppr.reflect's list; 0 without one)
};
PPR_END
PPR_SIZE_CHECK(PprFrameStats, 64);
// kTileClassCount must match PprFrameStats::dispatch.

PPR_BEGIN
// Tiles needed to cover `pixels` (partial tiles at the edges count).
PPR_INLINE uint pprTilesCovering(uint pixels) { return (pixels + kPprTileSize - 1u) / kPprTileSize; }

// A tile list entry: x in the low 16 bits, y in the high 16.
PPR_INLINE uint pprPackTile(uvec2 tile) { return tile.x | (tile.y << 16u); }
PPR_INLINE uvec2 pprUnpackTile(uint packed) { return uvec2(packed & 0xFFFFu, packed >> 16u); }
PPR_END

#endif
