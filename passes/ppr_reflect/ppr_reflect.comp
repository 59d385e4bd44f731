#version 460
#extension GL_GOOGLE_include_directive : require
#include "common/bindings.glsl"
#include "common/reflection.h"
#include "ppr_common/encoding.h"
#include "ppr_common/tiles.h"
#include "ppr_reflect/ppr_reflect.h"

// PPR step 3, the reflection pass: decode the offset stored at each reflector pixel, patch holes from
// the neighbour with the shortest offset, sample the lit scene filtered and unfiltered, and reduce
// the colour bleeding of the filtered sample. Writes the reflection image (common/reflection.h).
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

vec2 fullOffset(uint v) {
    PprDecoded d = pprDecode(v);
    return d.whole + d.fraction;
}

vec3 rgbToYCoCg(vec3 c) { return vec3(0.25 * c.r + 0.5 * c.g + 0.25 * c.b, 0.5 * c.r - 0.5 * c.b, -0.25 * c.r + 0.5 * c.g - 0.25 * c.b); }
vec3 yCoCgToRgb(vec3 c) { return vec3(c.x + c.y - c.z, c.x + c.z, c.x - c.y - c.z); }

// Keep the filtered colour unless it strays perceptually far from the point sample: luma and
// (luma-normalised) chroma are pulled towards the point sample separately, by how far apart they are.
vec3 reduceColorBleeding(vec3 filtered, vec3 unfiltered) {
    float exposure = frame.lightColor.w;  // compare as displayed, not in raw HDR units
    vec3 f = rgbToYCoCg(filtered * exposure), u = rgbToYCoCg(unfiltered * exposure);
    f.yz /= max(f.x, 1e-4);
    u.yz /= max(u.x, 1e-4);
    float lumaWeight = clamp(3.0 * abs(f.x - u.x), 0.0, 1.0);
    float chromaWeight = clamp(1.4 * length(f.yz - u.yz), 0.0, 1.0);
    float y = mix(f.x, u.x, lumaWeight);
    vec2 coCg = mix(f.yz, u.yz, chromaWeight) * y;
    return max(yCoCgToRgb(vec3(y, coCg)), vec3(0.0)) / exposure;
}

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

    // Hole filling: take the neighbour with the smallest offset when this pixel has no data, or when
    // that neighbour's offset is significantly (kPprHoleMinDistance) shorter — a hole in the first
    // reflection layer. The slides' four neighbours.
    ivec2 readPix = pix;
    if ((pc.flags & kPprHoleFilling) != 0u) {
        const ivec2 n1 = ivec2(1, 0), n2 = ivec2(0, 1), n3 = ivec2(1, 1), n4 = ivec2(-1, 0);
        uint v1 = fetchValue(pix + n1), v2 = fetchValue(pix + n2), v3 = fetchValue(pix + n3), v4 = fetchValue(pix + n4);
        uint vmin = min(min(min(v0, v1), min(v2, v3)), v4);
        bool fill = v0 == kPprClearValue || distance(fullOffset(v0), fullOffset(vmin)) > kPprHoleMinDistance;
        if (fill && vmin != v0) {
            if (vmin == v1) readPix = pix + n1;
            else if (vmin == v2) readPix = pix + n2;
            else if (vmin == v3) readPix = pix + n3;
            else readPix = pix + n4;
        }
    }
    PprDecoded d = pprDecode(fetchValue(readPix));
    if (!d.valid) {
        imageStore(outReflection, pix, vec4(0.0, 0.0, 0.0, kReflectionNone));
        if (pc.debugView == kDebugHoles) imageStore(outReflection, pix, vec4(1.0, 0.0, 0.0, 1.0));
        return;
    }

    // The offset as if this pixel had the neighbour's data: the point sample repeats the neighbour's
    // source; the filtered one moves the source the mirrored way along the offset.
    vec2 offsetFiltered = d.whole + d.fraction;
    vec2 offsetPoint = d.whole;
    vec2 shift = vec2(readPix - pix);
    if (readPix != pix) {
        vec2 dir = normalize(offsetFiltered);
        offsetPoint -= shift;
        offsetFiltered -= 2.0 * dir * dot(dir, shift);
    }
    vec2 centre = vec2(pix) + 0.5;
    vec3 filtered = textureLod(sceneLinear, (centre - offsetFiltered) * frame.invScreenSize, 0.0).rgb;
    vec3 unfiltered = textureLod(scenePoint, (centre - offsetPoint) * frame.invScreenSize, 0.0).rgb;
    vec3 color = unfiltered;
    if ((pc.flags & kPprFiltering) != 0u)
        color = (pc.flags & kPprAntiBleeding) != 0u ? reduceColorBleeding(filtered, unfiltered) : filtered;

    if (pc.debugView == kDebugHoles) {
        imageStore(outReflection, pix, vec4(readPix == pix ? vec3(0.0, 0.8, 0.0) : vec3(1.0, 0.85, 0.0), 1.0));
        return;
    }
    imageStore(outReflection, pix, vec4(color, readPix == pix ? kReflectionHit : kReflectionFilled));
}
