#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_KHR_shader_subgroup_basic : require
#extension GL_KHR_shader_subgroup_arithmetic : require
#include "common/bindings.glsl"
#include "ppr_common/tiles.h"
#include "tile_classify/tile_classify.h"

// One workgroup per screen tile: does the tile hold reflector-rectangle pixels (PPR's work), other
// reflective pixels (a screen-space fallback's), or neither? Appends the tile to each list it
// belongs to and counts it in that list's indirect dispatch arguments (Stachowiak 2015). For PPR it
// also reduces the tile's world-space bounds, which the projection pass's culling reads.
// Each of the kTileClassifyThreads invocations looks at one column of the tile and reduces it in
// registers; each subgroup then adds its answer with one shared atomic per value. One invocation per
// pixel cost 3.4x as much on lavapipe: 256 invocations' scheduling and barriers, not the fetches.
layout(local_size_x = kTileClassifyThreads) in;
layout(set = 0, binding = 1) uniform usampler2D reflectorTex;
layout(set = 0, binding = 2) uniform sampler2D materialTex;
layout(set = 0, binding = 3, scalar) buffer Args { TileDispatchArgs args[]; };
layout(set = 0, binding = 4, scalar) writeonly buffer Lists { uint tiles[]; };
layout(set = 0, binding = 5) uniform sampler2D depthTex;
layout(set = 0, binding = 6, scalar) writeonly buffer Bounds { PprTileBounds tileBounds[]; };
layout(push_constant, scalar) uniform Push { TileClassifyPush pc; };

shared uint classBits;
shared uvec3 boxLo, boxHi;  // order-preserving uints, so that integer min/max reduce floats exactly

uint orderedFromFloat(float f) {
    uint u = floatBitsToUint(f);
    return (u & 0x80000000u) != 0u ? ~u : u | 0x80000000u;
}
float floatFromOrdered(uint u) { return uintBitsToFloat((u & 0x80000000u) != 0u ? u & 0x7FFFFFFFu : ~u); }
vec3 floatFromOrdered(uvec3 u) { return vec3(floatFromOrdered(u.x), floatFromOrdered(u.y), floatFromOrdered(u.z)); }

void main() {
    if (gl_LocalInvocationIndex == 0u) {
        classBits = 0u;
        boxLo = uvec3(0xFFFFFFFFu);
        boxHi = uvec3(0u);
    }
    barrier();
    uint bits = 0u;
    uvec3 lo = uvec3(0xFFFFFFFFu), hi = uvec3(0u);
    ivec2 origin = ivec2(gl_WorkGroupID.xy) * int(kPprTileSize);
    for (uint i = gl_LocalInvocationIndex; i < kPprTileSize * kPprTileSize; i += kTileClassifyThreads) {
        ivec2 pix = origin + ivec2(i % kPprTileSize, i / kPprTileSize);
        if (any(greaterThanEqual(pix, ivec2(frame.screenSize)))) continue;
        uint id = texelFetch(reflectorTex, pix, 0).r;
        bool reflective = texelFetch(materialTex, pix, 0).b > 0.5;  // gbuffer.h: material b = reflective flag
        if (id != 0u && id <= pc.maxReflectorId) bits |= 1u << kTileClassPlanar;
        else if (reflective && id == 0u) bits |= 1u << kTileClassOther;
        if (pc.worldBounds == 0u) continue;
        float depth = texelFetch(depthTex, pix, 0).r;
        if (depth <= 0.0) continue;  // sky: no position to mirror (as in the projection pass)
        vec3 p = worldFromDepth((vec2(pix) + 0.5) * frame.invScreenSize, depth);
        uvec3 o = uvec3(orderedFromFloat(p.x), orderedFromFloat(p.y), orderedFromFloat(p.z));
        lo = min(lo, o);
        hi = max(hi, o);
    }
    bits = subgroupOr(bits);
    lo = subgroupMin(lo);
    hi = subgroupMax(hi);
    if (subgroupElect()) {
        if (bits != 0u) atomicOr(classBits, bits);
        if (lo.x <= hi.x) {  // the subgroup saw geometry
            atomicMin(boxLo.x, lo.x);
            atomicMin(boxLo.y, lo.y);
            atomicMin(boxLo.z, lo.z);
            atomicMax(boxHi.x, hi.x);
            atomicMax(boxHi.y, hi.y);
            atomicMax(boxHi.z, hi.z);
        }
    }
    barrier();
    if (gl_LocalInvocationIndex != 0u) return;
    if (pc.worldBounds != 0u) {
        PprTileBounds b;
        b.hasContent = boxLo.x <= boxHi.x ? 1u : 0u;
        b.lo = b.hasContent != 0u ? floatFromOrdered(boxLo) : vec3(0.0);
        b.hi = b.hasContent != 0u ? floatFromOrdered(boxHi) : vec3(0.0);
        b.pad0 = 0u;
        tileBounds[gl_WorkGroupID.y * pc.tilesX + gl_WorkGroupID.x] = b;
    }
    uint packed = pprPackTile(gl_WorkGroupID.xy);
    if ((classBits & (1u << kTileClassPlanar)) != 0u) {
        tiles[kTileClassPlanar * pc.tileCount + atomicAdd(args[kTileClassPlanar].x, 1u)] = packed;
    }
    if ((classBits & (1u << kTileClassOther)) != 0u) {
        tiles[kTileClassOther * pc.tileCount + atomicAdd(args[kTileClassOther].x, 1u)] = packed;
    }
}
