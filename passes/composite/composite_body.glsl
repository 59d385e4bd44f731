// Composite body, compiled twice: composite.comp (no reflection technique) and
// composite_reflect.comp (PPR_COMPOSITE_REFLECTION: blends the technique's reflection image).
#include "common/bindings.glsl"
#include "common/brdf.glsl"
#include "common/reflection.h"
#include "common/reflector_data.h"
#include "gpu/scene_data.h"
#include "lighting/lighting.h"

layout(local_size_x = kLightingGroupSize, local_size_y = kLightingGroupSize) in;
layout(set = 0, binding = 1) uniform sampler2D sceneColor;
layout(set = 0, binding = 2) uniform sampler2D depthTex;
layout(set = 0, binding = 3) uniform sampler2D normalTex;
layout(set = 0, binding = 4) uniform sampler2D albedoTex;
layout(set = 0, binding = 5) uniform sampler2D materialTex;
layout(set = 0, binding = 6) uniform usampler2D reflectorTex;
layout(set = 0, binding = 7, rgba16f) uniform writeonly image2D outColor;
layout(set = 0, binding = 8, scalar) readonly buffer Motions { MotionData motions[]; };  // the motion debug view
#ifdef PPR_COMPOSITE_REFLECTION
layout(set = 0, binding = 9) uniform sampler2D reflectionTex;
layout(set = 0, binding = 10, scalar) readonly buffer Reflectors { ReflectorData reflectors[]; };
#endif
#include "taa/taa_motion.glsl"
#include "taa/object_motion.glsl"

vec3 idColor(uint id) {
    uint h = id * 2654435761u;
    return vec3((h >> 8) & 255u, (h >> 16) & 255u, (h >> 24) & 255u) / 255.0;
}

void main() {
    ivec2 pix = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(pix, ivec2(frame.screenSize)))) return;
    vec3 c = texelFetch(sceneColor, pix, 0).rgb;
    uint id = texelFetch(reflectorTex, pix, 0).r;
    // Written to alpha (which nothing else reads): how much of the colour is the reflection, by which
    // the frame's TAA mixes a history fetched with the reflection's motion into the surface's.
    float reflectionWeight = 0.0;
#ifdef PPR_COMPOSITE_REFLECTION
    vec4 material = texelFetch(materialTex, pix, 0);
    bool reflective = id != 0u || material.b > 0.5;  // gbuffer.h: material b = reflective flag
    // Fetched only where it can be blended (and where a debug view draws it, below).
    bool drawsReflection = reflective || frame.debugView == kDebugIntermediate || frame.debugView == kDebugHoles || frame.debugView == kDebugTiles;
    vec4 reflection = drawsReflection ? texelFetch(reflectionTex, pix, 0) : vec4(0.0);
    if (reflective && reflection.a > 0.0) {
        // The reflection replaces the lit surface by the Fresnel term (Schlick, F0 from the material)
        // times the reflector's reflectance (or, off reflector rectangles, the surface's).
        float depth = texelFetch(depthTex, pix, 0).r;
        vec3 world = worldOfPixel(pix, depth);
        vec3 n = normalize(texelFetch(normalTex, pix, 0).xyz);
        vec3 albedo = texelFetch(albedoTex, pix, 0).rgb;
        float metallic = material.g;
        float nv = max(dot(n, normalize(frame.cameraPos.xyz - world)), 0.0);
        float reflectance = id != 0u ? reflectors[id - 1u].reflectance : surfaceReflectance(material.r);
        vec3 weight = fresnelSchlick(nv, mix(vec3(0.04), albedo, metallic)) * reflectance;
        c = mix(c, reflection.rgb, weight);
        reflectionWeight = (weight.r + weight.g + weight.b) / 3.0;
    }
#endif
    uint view = frame.debugView;
    if (view == kDebugAlbedo) c = texelFetch(albedoTex, pix, 0).rgb;
    else if (view == kDebugNormals) c = texelFetch(normalTex, pix, 0).xyz * 0.5 + 0.5;
    else if (view == kDebugRoughness) c = texelFetch(materialTex, pix, 0).rgb;
    else if (view == kDebugDepth) c = vec3(pow(texelFetch(depthTex, pix, 0).r, 0.25));
    else if (view == kDebugMotion) {
        float prevW;
        vec2 uv = (vec2(pix) + 0.5) * frame.invScreenSize;
        vec2 motion = (previousUvMoving(uv, texelFetch(depthTex, pix, 0).r, motionSlotAt(pix), prevW) - uv) * frame.screenSize;
        // Black = still; the hue gives the direction, the brightness the length (full at the range).
        float len = length(motion);
        vec2 dir = len > 0.0 ? motion / len : vec2(0.0);
        c = prevW > 0.0 ? vec3(0.5 + 0.5 * dir, 0.5) * min(len / kDebugMotionRange, 1.0) : vec3(1.0, 0.0, 1.0);
    }
    else if (view == kDebugReflectors) {
        if (id != 0u) c = mix(c, idColor(id), 0.6);
    }
#ifdef PPR_COMPOSITE_REFLECTION
    else if (view == kDebugIntermediate || view == kDebugHoles || view == kDebugTiles) {
        // Drawn by the PPR reflection pass (alpha marks what it drew); the scene is dimmed around it.
        c = mix(c * 0.25 * frame.lightColor.w, reflection.rgb, reflection.a);
    }
#endif
    // Debug views are shown without tonemapping curves distorting them too much: divide by exposure.
    if (view != kDebugNone && view != kDebugReflectors) c /= max(frame.lightColor.w, 1e-4);
    imageStore(outColor, pix, vec4(c, reflectionWeight));
}
