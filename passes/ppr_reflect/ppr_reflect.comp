#version 460
#extension GL_GOOGLE_include_directive : require
#include "common/bindings.glsl"
#include "common/brdf.glsl"
#include "common/reflection.h"
#include "common/reflector_data.h"
#include "gpu/scene_data.h"
#include "ppr_common/encoding.h"
#include "ppr_common/tiles.h"
#include "ppr_reflect/ppr_reflect.h"
#include "ssr_common/ssr.h"

// PPR step 3, the reflection pass: resolves each reflector pixel (ppr_common/ppr_resolve.glsl: decode,
// hole filling, filtered sample, anti-bleeding), then what the flat data cannot show: the rim, the
// contact march, the normal map, the environment, into the reflection image (common/reflection.h).
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
layout(set = 0, binding = 8) uniform sampler2D depthTex;   // reverse-Z: near / view distance, 0 = sky
layout(set = 0, binding = 9) uniform sampler2D normalTex;  // G-buffer normal (normal-mapped)
layout(set = 0, binding = 10, scalar) readonly buffer Reflectors { ReflectorData reflectors[]; };
layout(push_constant, scalar) uniform Push { PprReflectPush pc; };
#define ENV_BINDING 11  // the probe's data and cube (11, 12)
layout(set = 0, binding = 13, rg32f) uniform writeonly image2D outDistance;  // kPprWriteDistance: common/reflection.h
layout(set = 0, binding = 14) uniform sampler2D materialTex;  // G-buffer: alpha = motion slot (kPprWriteDistance)
// kPprListMappedHoles: the list's dispatch arguments and which slots of the planar list are listed; the list.
layout(set = 0, binding = 15, scalar) buffer MappedHoles { TileDispatchArgs mappedHoleArgs; uint mappedHoleListed[]; };
layout(set = 0, binding = 16, scalar) writeonly buffer MappedHoleTiles { uint mappedHoleTiles[]; };
#include "gbuffer/motion_slot.glsl"

// TAA's reflection history: the path eye → this pixel's surface → the reflected point seen at screen
// position `seen` (pixels), with that point's motion slot.
void storeDistance(ivec2 pix, vec2 seen) {
    ivec2 seenPix = clamp(ivec2(seen), ivec2(0), ivec2(frame.screenSize) - 1);
    vec3 surface = worldOfPixel(pix, texelFetch(depthTex, pix, 0).r);
    vec3 reflected = worldOfPixel(seenPix, texelFetch(depthTex, seenPix, 0).r);
    imageStore(outDistance, pix, vec4(length(surface - frame.cameraPos.xyz) + length(reflected - surface),
                                      pathTag(motionSlotOf(texelFetch(materialTex, seenPix, 0)), 0u), 0.0, 0.0));
}

// kPprListMappedHoles (indirect only): this pixel is one ppr.fallback.holes will march; list its tile
// once (the first pixel to flag the tile's slot appends it).
void listMappedHole() {
    if (atomicExchange(mappedHoleListed[gl_WorkGroupID.x], 1u) == 0u) mappedHoleTiles[atomicAdd(mappedHoleArgs.x, 1u)] = planarTiles[gl_WorkGroupID.x];
}

uint fetchValue(ivec2 p) {
    if (any(lessThan(p, ivec2(0))) || any(greaterThanEqual(p, ivec2(frame.screenSize)))) return kPprClearValue;
    return imageLoad(intermediate, p).r;
}

#include "common/environment.glsl"
#include "ppr_common/ppr_resolve.glsl"

// The flat reflection's colour at a located pixel: the rim's or the contact march's point sample, or
// the resolved one.
vec3 flatColor(PprResolved r, bool colorKnown) { return colorKnown ? r.color : pprColor(r, pc.flags); }

bool environmentUsesProbe() { return (pc.flags & kPprEnvironmentProbe) != 0u; }

// Clip coordinates to pixel coordinates; false behind the near plane or off screen.
bool screenFromClip(vec4 h, out vec2 pixel) {
    pixel = pixelFromClip(h);
    return h.w > frame.cameraPos.w && all(greaterThanEqual(pixel, vec2(0.0))) && all(lessThan(pixel, frame.screenSize));
}

// Projects a world point: pixel coordinates and its view distance (w); false as screenFromClip.
bool projectToScreen(vec3 p, out vec2 pixel, out float w) {
    vec4 h = frame.viewProj * vec4(p, 1.0);
    w = h.w;
    return screenFromClip(h, pixel);
}

#include "ppr_reflect/normal_map_hit.glsl"

// holes=1, a pixel on the reflector's rim that nothing was projected to: what stands on the edge (a
// mirror's frame, a wall meeting a floor mirror) continues into its reflection there, but the main
// view shows the part that touches the mirror only in slivers under a pixel wide. Take the
// neighbour off this reflector whose mirror image lands within kPprRimReach pixels of this one, if
// it stands clearly in front of the plane (the floor around a puddle lies in or under it).
bool rimContinuation(ivec2 pix, uint id, out vec2 source) {
    // The four neighbours' reflector ids in two gathers (left and up, then down and right); most
    // empty pixels lie inside the reflector and stop here. Beyond the screen the clamped gather
    // repeats this pixel's id: not a rim.
    uvec4 upperLeft = textureGather(reflectorTex, vec2(pix) * frame.invScreenSize, 0);
    uvec4 lowerRight = textureGather(reflectorTex, (vec2(pix) + 1.0) * frame.invScreenSize, 0);
    uvec4 ids = uvec4(upperLeft.x, upperLeft.z, lowerRight.x, lowerRight.z);
    if (all(equal(ids, uvec4(id)))) return false;
    const ivec2 around[4] = ivec2[4](ivec2(-1, 0), ivec2(0, -1), ivec2(0, 1), ivec2(1, 0));
    float nearest = kPprRimReach;
    bool found = false;
    for (int k = 0; k < 4; ++k) {
        if (ids[k] == id) continue;
        ivec2 q = pix + around[k];
        float depth = texelFetch(depthTex, q, 0).r;
        if (depth <= 0.0) continue;
        vec3 normal = reflectors[id - 1u].normal;
        vec3 p = worldOfPixel(q, depth);
        float height = dot(p - reflectors[id - 1u].center, normal);
        if (height <= kPprRimMinHeight * frame.cameraPos.w / depth) continue;  // view distance = near / depth
        vec2 image;
        float w;
        if (!projectToScreen(p - 2.0 * height * normal, image, w)) continue;
        float d = distance(image, vec2(pix) + 0.5);
        if (d < nearest) {
            nearest = d;
            source = vec2(q) + 0.5;
            found = true;
        }
    }
    return found;
}

// The reflected ray in clip space, where it is linear: clip(t) = origin + t * direction.
struct ClipRay {
    vec4 origin, direction;
};

// The point `along` the ray (metres): 0 in front of the depth buffer or off screen, 1 behind it
// within the thickness (a hit), 2 behind it farther than that. Behind means behind all four depth
// texels around the point: one pixel centre on an object next to its outline is not enough (the ray
// may pass over a ledge within that pixel).
uint contactTest(ClipRay ray, float along, out vec2 x) {
    vec4 h = ray.origin + along * ray.direction;
    float rayW = h.w;
    if (!screenFromClip(h, x)) return 0u;
    // In front of the texel under the point (most taps): in front of the farthest of the four too.
    float near = frame.cameraPos.w;  // view distance = near / depth
    float under = texelFetch(depthTex, ivec2(x), 0).r;
    if (under <= 0.0 || rayW <= near / under * 1.001) return 0u;
    vec4 depths = textureGather(depthTex, x * frame.invScreenSize, 0);
    float farthest = min(min(depths.x, depths.y), min(depths.z, depths.w)), nearest = max(max(depths.x, depths.y), max(depths.z, depths.w));
    if (farthest <= 0.0) return 0u;
    float farW = near / farthest, nearW = near / nearest;
    if (rayW <= farW * 1.001) return 0u;
    return rayW <= nearW + ssrThickness(nearW, kPprContactThickness, kPprContactThicknessScale) ? 1u : 2u;
}

// contact=1: the reflected ray from this pixel's surface toward the point its data reflects (seen at
// `source`), marched from the pixel: kPprContactTaps taps, kPprContactFirstTap screen pixels away
// and doubling. The main view cannot show what the ray meets first if that is hidden there (the
// underside of an object standing on the reflector). The nearest tap where the ray lies behind the
// depth buffer within the SSR thickness has hit that object; a tap behind it by more than that is
// refined by bisection toward where the ray went behind it, which may be within the thickness. The
// reflection shows what the depth buffer shows there. The taps are spaced by the screen segment to
// the source (where 1 / view distance is linear) but lie on the exact reflected ray: at a grazing
// angle a point of the pixel-centred segment can be a centimetre off the ray, inside a ledge the ray
// passes over.
bool contactHit(ivec2 pix, vec3 surface, vec3 dir, vec2 source, out vec2 hitPixel) {
    vec2 from = vec2(pix) + 0.5;
    float len = distance(source, from);
    if (len < 2.0 * kPprContactFirstTap) return false;
    ivec2 sourcePix = clamp(ivec2(source), ivec2(0), ivec2(frame.screenSize) - 1);
    float sourceDepth = texelFetch(depthTex, sourcePix, 0).r;
    float near = frame.cameraPos.w;
    float invFrom = texelFetch(depthTex, pix, 0).r / near, invTo = sourceDepth / near;
    // Sky: the ray's length to it is unknown; march the first metres of it.
    float reach = sourceDepth > 0.0 ? distance(surface, worldOfPixel(sourcePix, sourceDepth)) : 1.0 / invFrom;
    ClipRay ray = ClipRay(frame.viewProj * vec4(surface, 1.0), frame.viewProj * vec4(dir, 0.0));
    float tap = kPprContactFirstTap, visible = 0.0;
    for (uint k = 0u; k < kPprContactTaps && tap < len; ++k, tap *= 2.0) {
        float f = tap / len;
        float along = (sourceDepth > 0.0 ? f * invTo / mix(invFrom, invTo, f) : f) * reach;  // perspective-correct
        vec2 x;
        uint t = contactTest(ray, along, x);
        if (t == 1u) {
            hitPixel = floor(x) + 0.5;
            return true;
        }
        if (t == 0u) {
            visible = along;
            continue;
        }
        float hidden = along;
        for (uint i = 0u; i < kPprContactRefineSteps; ++i) {
            float mid = 0.5 * (visible + hidden);
            uint m = contactTest(ray, mid, x);
            if (m == 1u) {
                hitPixel = floor(x) + 0.5;
                return true;
            }
            if (m == 0u) visible = mid;
            else hidden = mid;
        }
        visible = along;
    }
    return false;
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
    bool listHoles = (pc.flags & kPprListMappedHoles) != 0u;
    if (!onReflector) {
        imageStore(outReflection, pix, vec4(0.0, 0.0, 0.0, kReflectionNone));
        // A reflector beyond PPR's budget is a hole to the fallback as well.
        if (listHoles && id != 0u && dot(normalize(texelFetch(normalTex, pix, 0).xyz), reflectors[id - 1u].normal) < kPprMappedHoleListCos)
            listMappedHole();
        return;
    }

    // The flat reflection's colour is fetched only where it is kept (flatColor): a normal-mapped
    // pixel's march usually replaces it.
    PprResolved r = pprLocate(pix, vec2(pix) + 0.5, 1.0, pc.flags);
    bool colorKnown = false;  // r.color holds the rim's or the contact march's point sample
    vec2 rim;
    if (!r.valid && (pc.flags & kPprHoleEnclosed) != 0u && rimContinuation(pix, id, rim)) {
        r.valid = true;
        colorKnown = true;
        r.color = textureLod(scenePoint, rim * frame.invScreenSize, 0.0).rgb;
        r.source = rim;
        r.readTexel = ivec2(rim);  // not this pixel's data: marked hole-filled
    }
    const uint normalModes = kPprNormalApprox | kPprNormalRaymarch;
    vec3 surface = (pc.flags & (normalModes | kPprEnvironment | kPprContactMarch)) != 0u
                       ? worldOfPixel(pix, texelFetch(depthTex, pix, 0).r)
                       : vec3(0.0);
    vec3 flatNormal = reflectors[id - 1u].normal;
    vec2 contact;
    vec3 n = flatNormal;
    float mappedCos = 1.0;
    if ((pc.flags & normalModes) != 0u) {
        vec3 mapped = normalize(texelFetch(normalTex, pix, 0).xyz);
        mappedCos = dot(mapped, flatNormal);
        if (mappedCos < kFlatNormalCos) n = mapped;
    }
    // A normal-mapped pixel (approx, raymarch) reflects along the mapped ray, not the flat one: no
    // contact march along the flat one (but with normal_refine=walk, which keeps the old pictures).
    bool followsMappedRay = n != flatNormal && (pc.flags & kPprNormalWalk) == 0u;
    bool contacted = r.valid && !followsMappedRay && (pc.flags & kPprContactMarch) != 0u &&
                     contactHit(pix, surface, reflect(normalize(surface - frame.cameraPos.xyz), flatNormal), r.source, contact);
    if (contacted) {
        colorKnown = true;
        r.color = textureLod(scenePoint, contact * frame.invScreenSize, 0.0).rgb;
        r.source = contact;
    }
    if ((pc.flags & kPprWriteDistance) != 0u && r.valid && pc.debugView == kDebugNone) storeDistance(pix, r.source);
    if (pc.debugView == kDebugHoles) {  // red: none; green: own data; yellow: a neighbour's; blue: the contact march's
        vec3 c = !r.valid ? vec3(1.0, 0.0, 0.0) : contacted ? vec3(0.1, 0.4, 1.0) : r.readTexel == pix ? vec3(0.0, 0.8, 0.0) : vec3(1.0, 0.85, 0.0);
        imageStore(outReflection, pix, vec4(c, 1.0));
        return;
    }
    if ((pc.flags & (normalModes | kPprEnvironment)) == 0u) {  // the slides' flat mirror, as it always was
        imageStore(outReflection, pix, r.valid ? vec4(flatColor(r, colorKnown), r.readTexel == pix ? kReflectionHit : kReflectionFilled)
                                               : vec4(0.0, 0.0, 0.0, kReflectionNone));
        return;
    }
    vec3 dir = reflect(normalize(surface - frame.cameraPos.xyz), n);
    if (!r.valid) {  // nothing projected here: the environment, or no reflection
        if (listHoles && mappedCos < kPprMappedHoleListCos) listMappedHole();
        bool env = (pc.flags & kPprEnvironment) != 0u;
        imageStore(outReflection, pix, env ? vec4(environmentRadiance(surface, dir), kReflectionEnvironment) : vec4(0.0, 0.0, 0.0, kReflectionNone));
        return;
    }
    vec3 color;
    vec2 seen = r.source;
    vec2 hit;
    if (n != flatNormal && dot(dir, flatNormal) > 0.0 && normalMappedHit(surface, dir, r.source, hit)) {
        // Averaged over the flat sample's footprint where that is minified (the normal map moves the
        // reflected point, not how much of the source one pixel covers).
        color = footprintSample(hit, r.halfStep);
        seen = hit;
    } else {
        color = flatColor(r, colorKnown);
    }
    if ((pc.flags & kPprEnvironment) != 0u) color = environmentBlend(color, seen, surface, dir);
    // The normal-mapped hit moved the reflected point: its path replaces the flat one stored above.
    if ((pc.flags & kPprWriteDistance) != 0u && seen != r.source) storeDistance(pix, seen);
    imageStore(outReflection, pix, vec4(color, r.readTexel == pix ? kReflectionHit : kReflectionFilled));
}
