#version 460
#extension GL_GOOGLE_include_directive : require
#include "common/bindings.glsl"
#include "ppr_common/tiles.h"
#include "tile_classify/tile_classify.h"

// Per screen tile: does it hold reflector-rectangle pixels (PPR's work), other reflective pixels (a
// screen-space fallback's), or neither? Appends the tile to each list it belongs to and counts it in
// that list's indirect dispatch arguments (Stachowiak 2015). kLanes invocations per tile (a
// specialization constant, by device: tile_classify.h), kTileClassifyGroupSize / kLanes tiles per
// workgroup, the tiles in row order (the workgroups too, in rows of kTileClassifyGroupsPerRow), as
// the reach pass lays them out. With one lane per tile (a CPU device: lanes are SIMD lanes over
// neighbouring tiles) there is no barrier and no shared memory; with several, they look at every
// kLanes-th 2x2 quad and add their answers with one shared atomic each.
layout(local_size_x = kTileClassifyGroupSize) in;
layout(constant_id = 0) const uint kLanes = kTileClassifyThreads;  // TileClassifyPass always specialises it
layout(set = 0, binding = 1) uniform usampler2D reflectorTex;
layout(set = 0, binding = 2) uniform sampler2D materialTex;
layout(set = 0, binding = 3, scalar) buffer Args { TileDispatchArgs args[]; };
layout(set = 0, binding = 4, scalar) writeonly buffer Lists { uint tiles[]; };
layout(push_constant, scalar) uniform Push { TileClassifyPush pc; };

const uint kTilesPerGroup = kTileClassifyGroupSize / kLanes;
shared uint classBits[kTilesPerGroup];

void main() {
    uint lid = gl_LocalInvocationIndex, slot = lid / kLanes, lane = lid % kLanes;
    uint group = gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x;  // rows of workgroups (TileClassifyPass)
    uint index = group * kTilesPerGroup + slot;
    bool inside = index < pc.tileCount;
    uvec2 tile = uvec2(index % pc.tilesX, index / pc.tilesX);
    uint bits = 0u;
    ivec2 origin = ivec2(tile) * int(kPprTileSize);
    // 2x2 pixel quads: one gather per texture reads four pixels. Beyond the screen's last row or
    // column the clamp-to-edge sampler repeats that row or column, which lies in this same tile.
    const uint quadsPerRow = kPprTileSize / 2u;
    for (uint i = lane; inside && i < quadsPerRow * quadsPerRow; i += kLanes) {
        ivec2 pix = origin + 2 * ivec2(i % quadsPerRow, i / quadsPerRow);
        if (any(greaterThanEqual(pix, ivec2(frame.screenSize)))) continue;
        vec2 corner = vec2(pix + 1) * frame.invScreenSize;  // the quad's shared corner
        uvec4 ids = textureGather(reflectorTex, corner, 0);
        vec4 reflective = textureGather(materialTex, corner, 2);  // gbuffer.h: material b = reflective flag
        // 1 <= id <= maxReflectorId as one unsigned compare (id 0 wraps to the largest value)
        if (any(lessThan(ids - 1u, uvec4(pc.maxReflectorId)))) bits |= 1u << kTileClassPlanar;
        if (any(greaterThan(mix(vec4(0.0), reflective, equal(ids, uvec4(0u))), vec4(0.5)))) bits |= 1u << kTileClassOther;
    }
    if (kLanes > 1u) {  // a specialization constant: uniform
        if (lane == 0u) classBits[slot] = 0u;
        barrier();
        if (bits != 0u) atomicOr(classBits[slot], bits);
        barrier();
        bits = classBits[slot];
    }
    if (lane != 0u || !inside) return;
    uint packed = pprPackTile(tile);
    if ((bits & (1u << kTileClassPlanar)) != 0u) tiles[kTileClassPlanar * pc.tileCount + atomicAdd(args[kTileClassPlanar].x, 1u)] = packed;
    if ((bits & (1u << kTileClassOther)) != 0u) tiles[kTileClassOther * pc.tileCount + atomicAdd(args[kTileClassOther].x, 1u)] = packed;
}
