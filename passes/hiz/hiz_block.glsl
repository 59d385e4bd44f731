// One invocation's share of the depth hierarchy (hiz.h): a square block of level-0 texels reduced
// alone, in registers, up to the block's single texel, storing every level on the way. Shared by the
// build (hiz_build.comp) and PPR's reach pass, which reads every depth texel of a tile anyway
// (ppr_reach.comp). Include after hiz/hiz.h; the includer declares the atlas
//     layout(r32f) uniform image2D hizAtlas;   (writeonly allowed)
// and defines
//     float hizQuad(ivec2 texel, inout float far);   // the level-1 texel: the min over its 2x2 quad of
//                                                    // the depth buffer; far: min-ed with the quad's
//                                                    // least depth sample on screen (hiz.h kHizFarLevel)
// which the walk calls once for each level-1 texel of the block.

void hizStore(uvec2 padded, uint level, ivec2 texel, float v) { imageStore(hizAtlas, hizLevelOrigin(padded, level) + texel, vec4(v)); }
void hizStoreFar(uvec2 padded, ivec2 texel, float far) { imageStore(hizAtlas, hizFarOrigin(padded) + texel, vec4(far)); }

// Bits 0, 2, 4… of i as x and 1, 3, 5… as y: the i-th position of a Morton walk.
uvec2 hizMortonPosition(uint i) {
    uvec2 v = uvec2(i, i >> 1u) & 0x5555u;
    v = (v | (v >> 1u)) & 0x3333u;
    v = (v | (v >> 2u)) & 0x0F0Fu;
    return (v | (v >> 4u)) & 0x00FFu;
}

// The block `block` of level `blockLevel` (2, 3 or 4): its level-2 texels in Morton order, each from
// its four level-1 texels; every fourth completes a level-3 texel, every sixteenth a level-4 one.
// pending3, pending4: the minimum so far of the current texel's texels below. Returns the block's
// texel of blockLevel, and in `far` the least depth sample of the block on screen; with blockLevel
// 3 or 4 the far values of its level-3 texels are stored too. min is exact, so the order of the walk
// changes no bit of the result.
float hizReduceBlock(uvec2 padded, ivec2 block, uint blockLevel, out float far) {
    float pending3 = kHizEmpty, pending4 = kHizEmpty;
    float far3 = kHizFarNone;  // the far value of the current level-3 texel so far
    far = kHizFarNone;
    uint texels = 1u << (2u * (blockLevel - 2u));  // level-2 texels in the block
    float v = kHizEmpty;
    for (uint i = 0u; i < texels; ++i) {
        ivec2 texel = block * int(1u << (blockLevel - 2u)) + ivec2(hizMortonPosition(i));
        ivec2 below = 2 * texel;
        float far2 = kHizFarNone;
        float a = hizQuad(below, far2), b = hizQuad(below + ivec2(1, 0), far2), c = hizQuad(below + ivec2(0, 1), far2),
              d = hizQuad(below + ivec2(1, 1), far2);
        far = min(far, far2);
        hizStore(padded, 1u, below, a);
        hizStore(padded, 1u, below + ivec2(1, 0), b);
        hizStore(padded, 1u, below + ivec2(0, 1), c);
        hizStore(padded, 1u, below + ivec2(1, 1), d);
        v = min(min(a, b), min(c, d));
        hizStore(padded, 2u, texel, v);
        if (blockLevel == 2u) continue;
        far3 = min(far3, far2);
        if ((i & 3u) != 3u) {
            pending3 = min(pending3, v);
            continue;
        }
        v = min(pending3, v);
        pending3 = kHizEmpty;
        ivec2 texel3 = block * int(1u << (blockLevel - 3u)) + ivec2(hizMortonPosition(i >> 2u));
        hizStore(padded, 3u, texel3, v);
        hizStoreFar(padded, texel3, far3);
        far3 = kHizFarNone;
        if (blockLevel == 3u) continue;
        if (((i >> 2u) & 3u) != 3u) {
            pending4 = min(pending4, v);
            continue;
        }
        v = min(pending4, v);
        pending4 = kHizEmpty;
        hizStore(padded, 4u, block * int(1u << (blockLevel - 4u)) + ivec2(hizMortonPosition(i >> 4u)), v);
    }
    return v;
}
