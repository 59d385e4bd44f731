#version 460
#extension GL_GOOGLE_include_directive : require
#include "common/bindings.glsl"
#include "hiz/hiz.h"
#include "hiz/hiz_level0.glsl"

// The depth hierarchy's levels 1.. (hiz.h) in one dispatch: a workgroup per coarsest cell, which the
// padding makes whole, so no level needs a texel from another workgroup. Level 1 is the minimum of
// each 2×2 quad of the depth buffer (as 1 − depth; beyond the screen, empty), every other level the
// minimum of the 2×2 texels below it. Level 0 is the depth buffer itself and is not built.
//
// Each invocation takes a square block of the cell (kThreads of them, in Morton order) and walks its
// level-2 texels in Morton order too, so that every fourth completes a level-3 texel and every
// sixteenth a level-4 one, up to the block's single texel: registers only. The group then reduces the
// blocks' texels in shared memory, one level per barrier. min is exact, so the order of the reduction
// changes no bit of the result. One dispatch instead of one per level: on lavapipe 1.2–1.4 ms instead
// of 2.4–2.9 at 1280x720 (docs/performance.md).
layout(local_size_x_id = 0) in;
layout(constant_id = 0) const uint kThreads = kHizThreads;  // HizPass always specialises it
layout(set = 0, binding = 1) uniform sampler2D depthTex;
layout(set = 0, binding = 2, r32f) uniform image2D atlas;

const uint kCellLevel = kHizLevels - 1u;  // the cell is one texel of the coarsest level
shared float reduced[2][kThreads];        // ping-pong: a level's texels, read while the next is written

// Bits 0, 2, 4… of i as x and 1, 3, 5… as y: the i-th position of a Morton walk.
uvec2 mortonPosition(uint i) {
    uvec2 v = uvec2(i, i >> 1u) & 0x5555u;
    v = (v | (v >> 1u)) & 0x3333u;
    v = (v | (v >> 2u)) & 0x0F0Fu;
    return (v | (v >> 4u)) & 0x00FFu;
}

float levelOne(ivec2 c) {
    ivec2 p = 2 * c;
    if (all(lessThan(p + 1, ivec2(frame.screenSize)))) {
        // The whole quad on screen: one gather (the sample point is the quad's shared corner).
        vec4 d = textureGather(depthTex, vec2(p + 1) * frame.invScreenSize, 0);
        return min(min(hizFromReverseZ(d.x), hizFromReverseZ(d.y)), min(hizFromReverseZ(d.z), hizFromReverseZ(d.w)));
    }
    return min(min(hizLevel0(depthTex, p), hizLevel0(depthTex, p + ivec2(1, 0))),
               min(hizLevel0(depthTex, p + ivec2(0, 1)), hizLevel0(depthTex, p + ivec2(1, 1))));
}

void store(uvec2 padded, uint level, ivec2 texel, float v) { imageStore(atlas, hizLevelOrigin(padded, level) + texel, vec4(v)); }

void main() {
    uvec2 padded = hizPaddedSize(uvec2(frame.screenSize));
    uint lid = gl_LocalInvocationIndex;
    // kThreads is 4^k: blocks of 64 / 2^k level-0 texels a side, reduced alone up to level blockLevel.
    uint blockLevel = kCellLevel - uint(findMSB(kThreads)) / 2u;
    ivec2 cell = ivec2(gl_WorkGroupID.xy);
    ivec2 block = cell * int(1u << (kCellLevel - blockLevel)) + ivec2(mortonPosition(lid));  // in level blockLevel's texels

    // The block's level-2 texels in Morton order, each from its four level-1 texels; every fourth
    // completes a level-3 texel, every sixteenth a level-4 one (blocks stop at level 2, 3 or 4:
    // hiz_threads ≥ 16). pending3, pending4: the minimum so far of the current texel's texels below.
    float pending3 = kHizEmpty, pending4 = kHizEmpty;
    uint texels = 1u << (2u * (blockLevel - 2u));  // level-2 texels in the block
    float v = kHizEmpty;
    for (uint i = 0u; i < texels; ++i) {
        ivec2 texel = block * int(1u << (blockLevel - 2u)) + ivec2(mortonPosition(i));
        ivec2 below = 2 * texel;
        float a = levelOne(below), b = levelOne(below + ivec2(1, 0)), c = levelOne(below + ivec2(0, 1)), d = levelOne(below + ivec2(1, 1));
        store(padded, 1u, below, a);
        store(padded, 1u, below + ivec2(1, 0), b);
        store(padded, 1u, below + ivec2(0, 1), c);
        store(padded, 1u, below + ivec2(1, 1), d);
        v = min(min(a, b), min(c, d));
        store(padded, 2u, texel, v);
        if (blockLevel == 2u) continue;
        if ((i & 3u) != 3u) {
            pending3 = min(pending3, v);
            continue;
        }
        v = min(pending3, v);
        pending3 = kHizEmpty;
        store(padded, 3u, block * int(1u << (blockLevel - 3u)) + ivec2(mortonPosition(i >> 2u)), v);
        if (blockLevel == 3u) continue;
        if (((i >> 2u) & 3u) != 3u) {
            pending4 = min(pending4, v);
            continue;
        }
        v = min(pending4, v);
        pending4 = kHizEmpty;
        store(padded, 4u, block * int(1u << (blockLevel - 4u)) + ivec2(mortonPosition(i >> 4u)), v);
    }
    // v is now the block's texel of blockLevel.
    reduced[0][lid] = v;
    uint count = kThreads, from = 0u;
    for (uint level = blockLevel + 1u; level <= kCellLevel; ++level) {
        barrier();
        count /= 4u;
        if (lid < count) {
            v = min(min(reduced[from][4u * lid], reduced[from][4u * lid + 1u]), min(reduced[from][4u * lid + 2u], reduced[from][4u * lid + 3u]));
            reduced[1u - from][lid] = v;
            store(padded, level, cell * int(1u << (kCellLevel - level)) + ivec2(mortonPosition(lid)), v);
        }
        from = 1u - from;
    }
}
