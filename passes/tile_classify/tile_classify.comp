#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_KHR_shader_subgroup_basic : require
#extension GL_KHR_shader_subgroup_arithmetic : require
#include "common/bindings.glsl"
#include "ppr_common/tiles.h"
#include "tile_classify/tile_classify.h"

// One workgroup per screen tile: does the tile hold reflector-rectangle pixels (PPR's work), other
// reflective pixels (a screen-space fallback's), or neither? Appends the tile to each list it
// belongs to and counts it in that list's indirect dispatch arguments (Stachowiak 2015).
// kThreads invocations (a specialization constant, by device: tile_classify.h) look at every
// kThreads-th pixel of the tile; each subgroup then adds its answer with one shared atomic. One
// invocation per pixel cost 3.4x as much on lavapipe: 256 invocations' scheduling and barriers.
layout(local_size_x_id = 0) in;
layout(constant_id = 0) const uint kThreads = kTileClassifyThreads;  // TileClassifyPass always specialises it
layout(set = 0, binding = 1) uniform usampler2D reflectorTex;
layout(set = 0, binding = 2) uniform sampler2D materialTex;
layout(set = 0, binding = 3, scalar) buffer Args { TileDispatchArgs args[]; };
layout(set = 0, binding = 4, scalar) writeonly buffer Lists { uint tiles[]; };
layout(push_constant, scalar) uniform Push { TileClassifyPush pc; };

shared uint classBits;

void main() {
    if (gl_LocalInvocationIndex == 0u) classBits = 0u;
    barrier();
    uint bits = 0u;
    ivec2 origin = ivec2(gl_WorkGroupID.xy) * int(kPprTileSize);
    // 2x2 pixel quads: one gather per texture reads four pixels. Beyond the screen's last row or
    // column the clamp-to-edge sampler repeats that row or column, which lies in this same tile.
    const uint quadsPerRow = kPprTileSize / 2u;
    for (uint i = gl_LocalInvocationIndex; i < quadsPerRow * quadsPerRow; i += kThreads) {
        ivec2 pix = origin + 2 * ivec2(i % quadsPerRow, i / quadsPerRow);
        if (any(greaterThanEqual(pix, ivec2(frame.screenSize)))) continue;
        vec2 corner = vec2(pix + 1) * frame.invScreenSize;  // the quad's shared corner
        uvec4 ids = textureGather(reflectorTex, corner, 0);
        vec4 reflective = textureGather(materialTex, corner, 2);  // gbuffer.h: material b = reflective flag
        // 1 <= id <= maxReflectorId as one unsigned compare (id 0 wraps to the largest value)
        if (any(lessThan(ids - 1u, uvec4(pc.maxReflectorId)))) bits |= 1u << kTileClassPlanar;
        if (any(greaterThan(mix(vec4(0.0), reflective, equal(ids, uvec4(0u))), vec4(0.5)))) bits |= 1u << kTileClassOther;
    }
    bits = subgroupOr(bits);
    if (subgroupElect() && bits != 0u) atomicOr(classBits, bits);
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
