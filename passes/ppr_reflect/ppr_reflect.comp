#version 460
#extension GL_GOOGLE_include_directive : require
#include "common/bindings.glsl"
#include "common/reflection.h"
#include "ppr_common/encoding.h"
#include "ppr_common/tiles.h"
#include "ppr_reflect/ppr_reflect.h"

// PPR step 3, the reflection pass: resolves each reflector pixel (ppr_common/ppr_resolve.glsl: decode,
// hole filling, filtered sample, anti-bleeding) into the reflection image (common/reflection.h).
// Dispatched over the whole screen or, indirectly, over the tiles that hold reflector pixels (the
// image is cleared first).
layout(local_size_x = kPprTileSize, local_size_y = kPprTileSize) in;
layout(set = 0, binding = 1, r32ui) uniform readonly uimage2D intermediate;
layout(set = 0, binding = 2) uniform sampler2D sceneLinear;  // the same image twice:
layout(set = 0, binding = 3) uniform sampler2D scenePoint;   // bilinear and point sampled
layout(set = 0, binding = 4) uniform usampler2D reflectorTex;
layout(set = 0, binding = 5, rgba16f) uniform writeonly image2D outReflection;
layout(set = 0, binding = 6, scalar) readonly buffer TileList { uint planarTiles[]; };  // class kTileClassPlanar first
layout(set = 0, binding = 7, scalar) readonly buffer TileSurvivors { uint tileSurvivors[]; };
layout(push_constant, scalar) uniform Push { PprReflectPush pc; };

uint fetchValue(ivec2 p) {
    if (any(lessThan(p, ivec2(0))) || any(greaterThanEqual(p, ivec2(frame.screenSize)))) return kPprClearValue;
    return imageLoad(intermediate, p).r;
}

#include "ppr_common/ppr_resolve.glsl"

vec3 hue(float angle) { return clamp(abs(fract(angle + vec3(0.0, 2.0 / 3.0, 1.0 / 3.0)) * 6.0 - 3.0) - 1.0, 0.0, 1.0); }

// Heat map of reflectors surviving per-tile culling: blue (1) → green → yellow → red (64 and more).
vec4 tileHeat(uvec2 tile, ivec2 pix) {
    uint n = tileSurvivors[tile.y * pc.tilesX + tile.x];
    if (n == 0u) return vec4(0.0);
    float t = clamp(log2(float(n)) / 6.0, 0.0, 1.0);
    vec3 c = t < 0.5 ? mix(vec3(0.1, 0.3, 1.0), vec3(0.1, 0.9, 0.2), t * 2.0) : mix(vec3(1.0, 0.9, 0.1), vec3(1.0, 0.1, 0.05), t * 2.0 - 1.0);
    bool border = any(equal(pix % ivec2(kPprTileSize), ivec2(0)));
    return vec4(border ? c * 0.5 : c, 0.6);
}

void main() {
    ivec2 pix = ivec2(gl_GlobalInvocationID.xy);
    if ((pc.flags & kPprIndirect) != 0u)
        pix = ivec2(pprUnpackTile(planarTiles[gl_WorkGroupID.x]) * kPprTileSize + gl_LocalInvocationID.xy);
    if (any(greaterThanEqual(pix, ivec2(frame.screenSize)))) return;
    uint id = texelFetch(reflectorTex, pix, 0).r;
    bool onReflector = id != 0u && id <= pc.maxReflectorId;
    uint v0 = fetchValue(pix);

    if (pc.debugView == kDebugTiles) {
        imageStore(outReflection, pix, tileHeat(uvec2(pix) / kPprTileSize, pix));
        return;
    }

    if (pc.debugView == kDebugIntermediate) {
        // The raw intermediate buffer: hue = offset direction, brightness = length (full at 256 px).
        PprDecoded d = pprDecode(v0);
        vec2 o = d.whole + d.fraction;
        vec3 c = d.valid ? hue(atan(o.y, o.x) / 6.2831853 + 0.5) * (0.25 + 0.75 * min(length(o) / 256.0, 1.0)) : vec3(0.0);
        imageStore(outReflection, pix, vec4(c, d.valid || onReflector ? 1.0 : 0.0));
        return;
    }
    if (!onReflector) {
        imageStore(outReflection, pix, vec4(0.0, 0.0, 0.0, kReflectionNone));
        return;
    }

    PprResolved r = pprResolve(pix, vec2(pix) + 0.5, 1.0, pc.flags);
    if (!r.valid) {
        imageStore(outReflection, pix, vec4(0.0, 0.0, 0.0, kReflectionNone));
        if (pc.debugView == kDebugHoles) imageStore(outReflection, pix, vec4(1.0, 0.0, 0.0, 1.0));
        return;
    }
    if (pc.debugView == kDebugHoles) {
        imageStore(outReflection, pix, vec4(r.readTexel == pix ? vec3(0.0, 0.8, 0.0) : vec3(1.0, 0.85, 0.0), 1.0));
        return;
    }
    imageStore(outReflection, pix, vec4(r.color, r.readTexel == pix ? kReflectionHit : kReflectionFilled));
}
