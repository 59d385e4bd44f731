// GLSL prelude shared by the passes: extensions and the frame-constants block at set 0 binding 0.
#extension GL_EXT_scalar_block_layout : require
#include "common/frame.h"

layout(set = 0, binding = 0, scalar) uniform FrameBlock { FrameConstants frame; };

// Clip coordinates to pixel coordinates (the inverse of the projection part of worldFromDepth).
vec2 pixelFromClip(vec4 h) { return (h.xy / h.w * 0.5 + 0.5) * frame.screenSize; }

vec3 worldFromDepth(vec2 uv, float depth) {
    vec4 p = frame.invViewProj * vec4(uv * 2.0 - 1.0, depth, 1.0);
    return p.xyz / p.w;
}

// The world position at pixel `pix`'s centre with depth `depth` (reverse-Z, as the depth buffer).
vec3 worldOfPixel(ivec2 pix, float depth) { return worldFromDepth((vec2(pix) + 0.5) * frame.invScreenSize, depth); }

// The NDC of pixel `pix`'s centre, to the bit as worldFromDepth((vec2(pix) + 0.5) * frame.invScreenSize, ·)
// computes it (the tile box of ppr_common/tile_box.h relies on the same x and y).
vec2 ndcOfPixelCentre(ivec2 pix) { return ((vec2(pix) + 0.5) * frame.invScreenSize) * 2.0 - 1.0; }
