#version 460
#extension GL_GOOGLE_include_directive : require
#include "common/bindings.glsl"
#include "common/reflector_data.h"
#include "ppr_common/ordered_float.glsl"
#include "ppr_common/tile_box.h"
#include "ppr_common/tile_culling.h"
#include "ppr_common/tiles.h"
#include "ppr_reach/ppr_reach.h"
#include "hiz/hiz.h"

// Before the projection pass, with per-tile culling and indirect dispatch: which screen tiles can
// be reflected at all? kLanes invocations per tile find the world-space box of the tile's pixels,
// grown to hold the positions the projection pass reconstructs (ppr_common/tile_box.h), and run the
// first test of its culling on it over the frame's reflectors on screen (the bounds pass's list):
// with up to kPprReachPerReflector of them reflector by reflector, beyond that per cull plane
// against the unions of the plane's rectangles and world boxes. A tile that fails has no survivor
// in the projection's culling, so it would write nothing there: the projection is not dispatched
// for it.
// The rest are listed, in no particular order and each with its box, for the projection's indirect
// dispatch and culling.
// Left-out tiles get a survivor count of 0 (debug=tiles).
// kLanes invocations per tile (a specialization constant, --set reach_threads: by device, ppr_reach.h),
// kPprReachGroupSize / kLanes tiles per workgroup, the tiles in row order (the workgroups too, in
// rows of kPprReachGroupsPerRow).
// With kWritesHierarchy (one lane per tile only: PprReachPass), the lane walks its tile's quads in
// the depth hierarchy's block order and stores the hierarchy's levels 1..kHizTileLevel of the tile
// from the same gathers (hiz/hiz_block.glsl), which the hierarchy's build then does not read again.
layout(local_size_x = kPprReachGroupSize) in;
layout(constant_id = 0) const uint kLanes = kPprReachThreads;  // PprReachPass always specialises it
layout(constant_id = 1) const bool kWritesHierarchy = false;
layout(set = 0, binding = 1) uniform sampler2D depthTex;
layout(set = 0, binding = 2, scalar) readonly buffer Reflectors { ReflectorData reflectors[]; };
layout(set = 0, binding = 3, scalar) readonly buffer Bounds { PprReflectorBounds bounds[]; };
layout(set = 0, binding = 4, scalar) readonly buffer PlaneLeaders { uint planeLeaders[]; };
layout(set = 0, binding = 5, scalar) buffer Args { TileDispatchArgs args; };
layout(set = 0, binding = 6, scalar) writeonly buffer ReachTiles { PprReachedTile reachTiles[]; };
layout(set = 0, binding = 7, scalar) writeonly buffer TileSurvivors { uint tileSurvivors[]; };
layout(set = 0, binding = 8, scalar) buffer Stats { PprFrameStats stats; };
layout(set = 0, binding = 9, scalar) readonly buffer Visible { PPR_VISIBLE_REFLECTORS; };
layout(set = 0, binding = 10, r32f) uniform writeonly image2D hizAtlas;  // kWritesHierarchy; else a stand-in
layout(push_constant, scalar) uniform Push { PprReachPush pc; };

const uint kTilesPerGroup = kPprReachGroupSize / kLanes;

// Per tile of the workgroup: its box as order-preserving uints, the least depth of its points (the
// bits of a positive float: tile_box.h) and whether a lane found it reachable.
shared uvec3 tileLo[kTilesPerGroup], tileHi[kTilesPerGroup];
shared uint tileLeastDepth[kTilesPerGroup];
shared uint tileReached[kTilesPerGroup];

// This invocation's share of its tile's box, as order-preserving uints, and of its least depth (addQuad).
uvec3 boxLo = uvec3(0xFFFFFFFFu), boxHi = uvec3(0u);
float leastDepth = 1.0;

// The points of the 2x2 pixel quad whose top-left pixel is `quad`, added to the box (tile_box.h: the
// pixels' positions with the matrix terms of the quad's two columns and two rows shared; the box,
// grown in main, holds the positions the projection pass reconstructs: it culls with that box, listed
// with the tile below, and does not reduce its own). One gather; its order: (0,1), (1,1), (1,0),
// (0,0). Returns the quad's texel of the depth hierarchy's level 1: the min of 1 − depth over it,
// empty beyond the screen; `far` is min-ed with its least depth on screen (hiz.h kHizFarLevel).
float addQuad(ivec2 quad, inout float far) {
    if (any(greaterThanEqual(quad, ivec2(frame.screenSize)))) return kHizEmpty;
    const ivec2 corners[4] = ivec2[4](ivec2(0, 1), ivec2(1, 1), ivec2(1, 0), ivec2(0, 0));
    vec4 depths = textureGather(depthTex, vec2(quad + 1) * frame.invScreenSize, 0);
    vec2 ndcFirst = ndcOfPixelCentre(quad), ndcSecond = ndcOfPixelCentre(quad + 1);
    vec4 columnTerms[2] = vec4[2](pprBoxColumnTerm(frame.invViewProj, ndcFirst.x), pprBoxColumnTerm(frame.invViewProj, ndcSecond.x));
    vec4 rowTerms[2] = vec4[2](pprBoxRowTerm(frame.invViewProj, ndcFirst.y), pprBoxRowTerm(frame.invViewProj, ndcSecond.y));
    float nearest = kHizEmpty;
    for (uint c = 0u; c < 4u; ++c) {
        ivec2 pix = quad + corners[c];
        if (any(greaterThanEqual(pix, ivec2(frame.screenSize)))) continue;  // the clamped gather repeats the edge
        nearest = min(nearest, hizFromReverseZ(depths[c]));
        far = min(far, depths[c]);
        if (depths[c] <= 0.0) continue;  // sky
        leastDepth = min(leastDepth, depths[c]);
        uvec3 ordered = orderedFromFloat(pprBoxPoint(frame.invViewProj, columnTerms[corners[c].x], rowTerms[corners[c].y], depths[c]));
        boxLo = min(boxLo, ordered);
        boxHi = max(boxHi, ordered);
    }
    return nearest;
}

float hizQuad(ivec2 texel, inout float far) { return addQuad(2 * texel, far); }
#include "hiz/hiz_block.glsl"

// The projection's first culling test, reflector by reflector (this lane's share: every kLanes-th):
// does the tile's mirror image in the reflector's plane meet its screen rectangle, and its hit region
// the reflector's rectangle? (pprTileMayReachReflector, with the hit region built only for a plane
// one of whose reflectors passes the rectangle test: most tiles' mirror images miss every rectangle.
// On lavapipe this test was a third of the pass's time; the lazy hit region saves 12 % of the pass.)
bool reachesAReflector(vec3 boxLo, vec3 boxHi, uint lane) {
    uint plane = kPprNoCullPlane;  // the plane `mirrored` and the hit region belong to
    uvec2 mirrored = uvec2(kPprEmptyRectLo, kPprEmptyRectHi);
    ReflectorData leader;
    bool hitKnown = false;
    vec3 hitLo = vec3(0.0), hitHi = vec3(0.0);
    for (uint k = lane; k < visibleCounts.reflecting; k += kLanes) {
        uint i = visibleLists[k];
        PprReflectorBounds b = bounds[i];
        ReflectorData r = reflectors[i];
        // Coplanar reflectors are mostly neighbours: mirror once per run of one plane.
        if (r.cullPlane != kPprNoCullPlane && r.cullPlane != plane) {
            plane = r.cullPlane;
            leader = reflectors[planeLeaders[plane]];
            mirrored = pprTileReflectedRect(boxLo, boxHi, leader.normal, leader.center, frame.viewProj, frame.screenSize);
            hitKnown = false;
        }
        if (!pprTileMayReachReflectorOnScreen(r, b, mirrored)) continue;
        if (r.cullPlane == kPprNoCullPlane) return true;
        if (!hitKnown) {
            pprTileHitRegion(boxLo, boxHi, leader.normal, leader.center, frame.cameraPos.xyz, hitLo, hitHi);
            hitKnown = true;
        }
        if (pprRectangleMeetsBox(r, hitLo, hitHi)) return true;
    }
    return false;
}

// The same with each plane's reflectors merged (the bounds pass's PprCullPlaneBounds): does the
// tile's mirror image meet the union of the plane's screen rectangles, and its hit region the union
// of their world boxes? Coarser, but its cost per tile does not grow with the reflector count.
bool reachesAPlane(vec3 boxLo, vec3 boxHi, uint lane) {
    if (visibleCounts.untabled != 0u) return true;  // judged on its own rectangle: it keeps every tile
    for (uint plane = lane; plane < pc.cullPlaneCount; plane += kLanes) {
        PprCullPlaneBounds merged = cullPlaneBounds[plane];
        if (merged.loX > merged.hiX) continue;  // no reflecting rectangle in this plane
        // The plane's reflectors as one chunk summary (pprTileMayReachChunk), the hit region built
        // only when the mirror image meets their rectangle.
        PprCullChunk chunk = PprCullChunk(uvec2(merged.loX | (merged.loY << 16u), merged.hiX | (merged.hiY << 16u)),
                                          floatFromOrdered(merged.boxLo), plane, floatFromOrdered(merged.boxHi), 0u);
        ReflectorData leader = reflectors[planeLeaders[plane]];
        uvec2 mirrored = pprTileReflectedRect(boxLo, boxHi, leader.normal, leader.center, frame.viewProj, frame.screenSize);
        if (!pprRectsOverlap(mirrored, chunk.rect)) continue;
        vec3 hitLo, hitHi;
        pprTileHitRegion(boxLo, boxHi, leader.normal, leader.center, frame.cameraPos.xyz, hitLo, hitHi);
        if (pprTileMayReachChunk(chunk, mirrored, hitLo, hitHi)) return true;
    }
    return false;
}

void main() {
    uint lid = gl_LocalInvocationIndex, slot = lid / kLanes, lane = lid % kLanes;
    uint group = gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x;  // rows of workgroups (PprReachPass)
    uint index = group * kTilesPerGroup + slot;
    bool inside = index < pc.tilesX * pc.tilesY;
    uvec2 tile = uvec2(index % pc.tilesX, index / pc.tilesX);
    if (lane == 0u) {
        tileLo[slot] = uvec3(0xFFFFFFFFu);
        tileHi[slot] = uvec3(0u);
        tileLeastDepth[slot] = floatBitsToUint(1.0);
        tileReached[slot] = 0u;
    }
    barrier();

    // The box of the tile's points (addQuad), each lane from its share of the tile's 2x2 quads.
    if (inside) {
        if (kWritesHierarchy && kLanes == 1u) {  // specialization constants: uniform
            float far;
            hizReduceBlock(hizPaddedSize(uvec2(frame.screenSize)), ivec2(tile), kHizTileLevel, far);
        } else {
            const uint quadsPerRow = kPprTileSize / 2u;
            float far = kHizFarNone;  // unused without the hierarchy
            for (uint k = lane; k < quadsPerRow * quadsPerRow; k += kLanes)
                addQuad(ivec2(tile) * int(kPprTileSize) + 2 * ivec2(k % quadsPerRow, k / quadsPerRow), far);
        }
        if (boxLo.x <= boxHi.x) {
            atomicMin(tileLo[slot].x, boxLo.x);
            atomicMin(tileLo[slot].y, boxLo.y);
            atomicMin(tileLo[slot].z, boxLo.z);
            atomicMax(tileHi[slot].x, boxHi.x);
            atomicMax(tileHi[slot].y, boxHi.y);
            atomicMax(tileHi[slot].z, boxHi.z);
            atomicMin(tileLeastDepth[slot], floatBitsToUint(leastDepth));
        }
    }
    barrier();
    bool hasContent = inside && tileLo[slot].x <= tileHi[slot].x;
    vec3 lo = vec3(0.0), hi = vec3(0.0);  // the tile's box, grown to hold the projection's positions
    if (hasContent) {
        lo = floatFromOrdered(tileLo[slot]);
        hi = floatFromOrdered(tileHi[slot]);
        pprPadTileBox(frame.invViewProj, uintBitsToFloat(tileLeastDepth[slot]), lo, hi);
        bool reached = visibleCounts.reflecting <= kPprReachPerReflector ? reachesAReflector(lo, hi, lane) : reachesAPlane(lo, hi, lane);
        if (reached) atomicOr(tileReached[slot], 1u);
    }
    barrier();
    if (lane != 0u || !inside) return;
    if (hasContent) atomicAdd(stats.tilesWithContent, 1u);
    if (tileReached[slot] != 0u) reachTiles[atomicAdd(args.x, 1u)] = PprReachedTile(uvec4(orderedFromFloat(lo), pprPackTile(tile)), uvec4(orderedFromFloat(hi), 0u));
    else tileSurvivors[index] = 0u;
}
