#version 460
#extension GL_GOOGLE_include_directive : require
#include "common/bindings.glsl"
#include "hiz/hiz.h"
#include "ppr_common/tiles.h"

// The depth hierarchy's levels 1.. (hiz.h) in one dispatch: a workgroup per coarsest cell, which the
// padding makes whole, so no level needs a texel from another workgroup. Level 1 is the minimum of
// each 2×2 quad of the depth buffer (as 1 − depth; beyond the screen, empty), every other level the
// minimum of the 2×2 texels below it. Level 0 is the depth buffer itself and is not built.
//
// Each invocation takes a square block of the cell (kThreads of them, in Morton order) and walks its
// level-2 texels in Morton order too, so that every fourth completes a level-3 texel and every
// sixteenth a level-4 one, up to the block's single texel: registers only (hiz/hiz_block.glsl, which
// PPR's reach pass runs over its tiles as well: kFineLevelsBuilt). The group then reduces the
// blocks' texels in shared memory, one level per barrier. min is exact, so the order of the reduction
// changes no bit of the result. One dispatch instead of one per level: on lavapipe 1.2–1.4 ms instead
// of 2.4–2.9 at 1280x720 (docs/performance.md).
layout(local_size_x_id = 0) in;
layout(constant_id = 0) const uint kThreads = kHizThreads;  // HizPass always specialises it
// PPR's reach pass has stored levels 1..kHizTileLevel of every tile of the screen: a block inside the
// tile grid is read at its own level instead of walked (blocks beyond it, the padding, still are).
layout(constant_id = 1) const bool kFineLevelsBuilt = false;
layout(set = 0, binding = 1) uniform sampler2D depthTex;
layout(set = 0, binding = 2, r32f) uniform image2D hizAtlas;

const uint kCellLevel = kHizLevels - 1u;  // the cell is one texel of the coarsest level
shared float reduced[2][kThreads];        // ping-pong: a level's texels, read while the next is written
shared float blockFar[kThreads];          // with blocks of level 2: their far values (hiz.h kHizFarLevel)

float hizQuad(ivec2 c, inout float far) {
    ivec2 p = 2 * c;
    if (all(lessThan(p + 1, ivec2(frame.screenSize)))) {
        // The whole quad on screen: one gather (the sample point is the quad's shared corner).
        vec4 d = textureGather(depthTex, vec2(p + 1) * frame.invScreenSize, 0);
        far = min(far, min(min(d.x, d.y), min(d.z, d.w)));
        return min(min(hizFromReverseZ(d.x), hizFromReverseZ(d.y)), min(hizFromReverseZ(d.z), hizFromReverseZ(d.w)));
    }
    // At the screen's edge: texel by texel, the padding empty and not counted in the far value.
    float v = kHizEmpty;
    for (int k = 0; k < 4; ++k) {
        ivec2 q = p + ivec2(k & 1, k >> 1);
        if (any(greaterThanEqual(q, ivec2(frame.screenSize)))) continue;
        float depth = texelFetch(depthTex, q, 0).r;
        far = min(far, depth);
        v = min(v, hizFromReverseZ(depth));
    }
    return v;
}
#include "hiz/hiz_block.glsl"

// Whether PPR's reach pass stored this texel of `level` (<= kHizTileLevel) and the far values in it:
// with kFineLevelsBuilt, the texels inside the screen's tiles (hiz_threads >= 16 keeps blocks within a tile).
bool builtByReach(ivec2 texel, uint level) {
    uvec2 screen = uvec2(frame.screenSize);
    ivec2 tileGrid = ivec2(pprTilesCovering(screen.x), pprTilesCovering(screen.y));  // the tiles ppr.reach walked
    return kFineLevelsBuilt && all(lessThan(texel >> int(kHizTileLevel - level), tileGrid));
}

void main() {
    uvec2 padded = hizPaddedSize(uvec2(frame.screenSize));
    uint lid = gl_LocalInvocationIndex;
    // kThreads is 4^k: blocks of 64 / 2^k level-0 texels a side, reduced alone up to level blockLevel.
    uint blockLevel = kCellLevel - uint(findMSB(kThreads)) / 2u;
    ivec2 cell = ivec2(gl_WorkGroupID.xy);
    ivec2 block = cell * int(1u << (kCellLevel - blockLevel)) + ivec2(hizMortonPosition(lid));  // in level blockLevel's texels

    float far = kHizFarNone;
    float v = builtByReach(block, blockLevel) ? imageLoad(hizAtlas, hizLevelOrigin(padded, blockLevel) + block).r : hizReduceBlock(padded, block, blockLevel, far);
    // v is now the block's texel of blockLevel.
    reduced[0][lid] = v;
    if (blockLevel < kHizFarLevel) blockFar[lid] = far;
    uint count = kThreads, from = 0u;
    for (uint level = blockLevel + 1u; level <= kCellLevel; ++level) {
        barrier();
        count /= 4u;
        if (lid < count) {
            v = min(min(reduced[from][4u * lid], reduced[from][4u * lid + 1u]), min(reduced[from][4u * lid + 2u], reduced[from][4u * lid + 3u]));
            reduced[1u - from][lid] = v;
            ivec2 texel = cell * int(1u << (kCellLevel - level)) + ivec2(hizMortonPosition(lid));
            hizStore(padded, level, texel, v);
            // Blocks of level 2: the level-3 texels' far values from theirs (a level-3 texel lies in one
            // PPR tile, so its blocks were all walked or all stored by the reach pass).
            if (level == kHizFarLevel && !builtByReach(texel, level))
                hizStoreFar(padded, texel, min(min(blockFar[4u * lid], blockFar[4u * lid + 1u]), min(blockFar[4u * lid + 2u], blockFar[4u * lid + 3u])));
        }
        from = 1u - from;
    }
}
