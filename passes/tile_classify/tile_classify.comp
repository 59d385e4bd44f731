#version 460
#extension GL_GOOGLE_include_directive : require
#include "common/bindings.glsl"
#include "ppr_common/tiles.h"
#include "tile_classify/tile_classify.h"

// One workgroup per screen tile: does the tile hold reflector-rectangle pixels (PPR's work), other
// reflective pixels (a screen-space fallback's), or neither? Appends the tile to each list it
// belongs to and counts it in that list's indirect dispatch arguments (Stachowiak 2015).
layout(local_size_x = kPprTileSize, local_size_y = kPprTileSize) in;
layout(set = 0, binding = 1) uniform usampler2D reflectorTex;
layout(set = 0, binding = 2) uniform sampler2D materialTex;
layout(set = 0, binding = 3, scalar) buffer Args { TileDispatchArgs args[]; };
layout(set = 0, binding = 4, scalar) writeonly buffer Lists { uint tiles[]; };
layout(push_constant, scalar) uniform Push { TileClassifyPush pc; };

shared uint classBits;

void main() {
    if (gl_LocalInvocationIndex == 0u) classBits = 0u;
    barrier();
    ivec2 pix = ivec2(gl_GlobalInvocationID.xy);
    if (all(lessThan(pix, ivec2(frame.screenSize)))) {
        uint id = texelFetch(reflectorTex, pix, 0).r;
        bool reflective = texelFetch(materialTex, pix, 0).b > 0.5;  // gbuffer.h: material b = reflective flag
        if (id != 0u && id <= pc.maxReflectorId) atomicOr(classBits, 1u << kTileClassPlanar);
        else if (reflective && id == 0u) atomicOr(classBits, 1u << kTileClassOther);
    }
    barrier();
    if (gl_LocalInvocationIndex != 0u) return;
    uint packed = pprPackTile(gl_WorkGroupID.xy);
    if ((classBits & (1u << kTileClassPlanar)) != 0u) {
        tiles[kTileClassPlanar * pc.tileCount + atomicAdd(args[kTileClassPlanar].x, 1u)] = packed;
    }
    if ((classBits & (1u << kTileClassOther)) != 0u) {
        tiles[kTileClassOther * pc.tileCount + atomicAdd(args[kTileClassOther].x, 1u)] = packed;
    }
}
