// The depth hierarchy of ssr-hiz (and PPR's fallback), host/device shared.
//
// Depth is stored as 1 − reverse-Z depth: 0 at the near plane, 1 at infinity (sky). Like reverse-Z
// depth it is affine along a ray's screen-space segment, and the nearest surface in a cell is the
// minimum, so every level is a min-reduction of the one below (Uludag 2014).
//
// Level 0 is the depth buffer itself, read as 1 − depth where the march needs it (a copy cost a
// full-screen store per frame, docs/performance.md). Levels 1.. live in one r32f atlas image, stacked
// in a column from its top-left corner. The screen is padded up to a multiple of the coarsest cell so
// every level is exactly half the one below: level L's texel c covers level-0 texels
// [c·2^L, (c+1)·2^L), with no partial cells at the edges. Level-0 texels beyond the screen (padding)
// hold 1 (nothing there). Beside level 2 lie the far values of the 8x8 cells (kHizFarLevel).
#ifndef PPR_HIZ_H
#define PPR_HIZ_H
#include "shader/shared.h"

PPR_CONST(uint, kHizLevels, 7u)        // levels 0..6: the coarsest cell is 64 px
PPR_CONST(float, kHizEmpty, 1.0f)      // sky and padding
// Levels 1..kHizTileLevel of a 16x16 PPR tile: what PPR's reach pass, which reads every depth texel of
// the tile for its box, stores on the way when a fallback will march the hierarchy (ppr_reach.comp);
// the build then only adds the levels above (hiz_build.comp, kFineLevelsBuilt).
PPR_CONST(uint, kHizTileLevel, 4u)
// The farthest surface of each 8x8 cell (level kHizFarLevel's texels): the least reverse-Z depth over
// the cell's pixels on screen (0 where one of them is sky, kHizFarNone where none is on screen),
// stored in the atlas beside level 2, which leaves that space free (hizFarOrigin). Where the march
// walks level-0 pixels behind an object, a cell whose farthest surface the ray stays behind by more
// than the thickness cannot be hit anywhere on the ray's way through it: it crosses the cell in one
// step (ssr_hiz.comp, --set hiz_skip). Written by whoever writes the cell's level 3 near values.
PPR_CONST(uint, kHizFarLevel, 3u)
PPR_CONST(float, kHizFarNone, 1.0f)
// The build is one dispatch, a workgroup per coarsest cell (hiz_build.comp). Its invocations each
// reduce a square block of the cell alone, up to the block's one texel, and the group reduces those,
// a level per barrier: --set hiz_threads (specialization constant 0; 16, 64 or 256 invocations:
// blocks of 16, 8 or 4 level-0 texels a side). On a CPU device 16, because lavapipe runs a
// workgroup's invocations as 8-wide SIMD batches and pays per batch, most at a barrier; on a GPU
// 256, so that many invocations share the reads.
PPR_CONST(uint, kHizThreads, 16u)
PPR_CONST(uint, kHizThreadsGpu, 256u)

PPR_BEGIN
// The screen padded up to a multiple of the coarsest cell.
PPR_INLINE uvec2 hizPaddedSize(uvec2 screen) {
    uint cell = 1u << (kHizLevels - 1u);
    return ((screen + uvec2(cell - 1u)) / cell) * cell;
}
PPR_INLINE uvec2 hizLevelSize(uvec2 padded, uint level) { return uvec2(padded.x >> level, padded.y >> level); }
// Top-left texel of a level (≥ 1) in the atlas: below levels 1..level−1, whose heights padded.y/2,
// padded.y/4, ... sum to padded.y − padded.y/2^(level−1) exactly (padded.y is a multiple of the
// coarsest cell). Closed form, not a loop: the march calls it at every change of level.
PPR_INLINE ivec2 hizLevelOrigin(uvec2 padded, uint level) { return ivec2(0, int(padded.y - (padded.y >> (level - 1u)))); }
// Top-left texel of the far values (kHizFarLevel): right of level 2, which is a quarter of the padded
// width wide, in the rows of level 2.
PPR_INLINE ivec2 hizFarOrigin(uvec2 padded) { return ivec2(int(padded.x / 4u), int(padded.y / 2u)); }
// Levels 1.. stacked: half the padded width, and heights that sum to less than the padded height.
PPR_INLINE uvec2 hizAtlasSize(uvec2 padded) { return uvec2(padded.x / 2u, padded.y); }
// Level-0 value of a depth-buffer sample (reverse-Z, 0 = sky).
PPR_INLINE float hizFromReverseZ(float reverseZ) { return 1.0f - reverseZ; }
PPR_END

#endif
