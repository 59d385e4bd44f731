#version 460
#extension GL_GOOGLE_include_directive : require
#include "common/bindings.glsl"
#include "common/brdf.glsl"
#include "lighting/lighting.h"

layout(local_size_x = kLightingGroupSize, local_size_y = kLightingGroupSize) in;
layout(set = 0, binding = 1) uniform sampler2D depthTex;
layout(set = 0, binding = 2) uniform sampler2D normalTex;
layout(set = 0, binding = 3) uniform sampler2D albedoTex;
layout(set = 0, binding = 4) uniform sampler2D materialTex;
layout(set = 0, binding = 5) uniform sampler2DShadow shadowMap;
layout(set = 0, binding = 6, rgba16f) uniform writeonly image2D outColor;

float shadowFactor(vec3 world, vec3 n) {
    // Offset along the normal so grazing surfaces do not self-shadow.
    vec4 p = frame.lightViewProj * vec4(world + n * 0.02, 1.0);
    vec3 s = p.xyz / p.w;
    vec2 uv = s.xy * 0.5 + 0.5;
    if (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0))) || s.z <= 0.0) return 1.0;
    float texel = frame.lightDir.w;
    float sum = 0.0;
    for (int y = -1; y <= 1; ++y)
        for (int x = -1; x <= 1; ++x) sum += texture(shadowMap, vec3(uv + vec2(x, y) * texel, s.z));
    return sum / 9.0;
}

void main() {
    ivec2 pix = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(pix, ivec2(frame.screenSize)))) return;
    vec2 uv = (vec2(pix) + 0.5) * frame.invScreenSize;
    float depth = texelFetch(depthTex, pix, 0).r;
    vec3 world = worldFromDepth(uv, depth);
    vec3 toCamera = frame.cameraPos.xyz - world;
    if (depth <= 0.0) {  // sky
        vec3 dir = normalize(worldFromDepth(uv, 1.0) - frame.cameraPos.xyz);
        imageStore(outColor, pix, vec4(skyRadiance(dir), 1.0));
        return;
    }
    vec3 n = normalize(texelFetch(normalTex, pix, 0).xyz);
    vec3 albedo = texelFetch(albedoTex, pix, 0).rgb;
    vec4 mat = texelFetch(materialTex, pix, 0);
    float roughness = mat.r, metallic = mat.g;
    vec3 v = normalize(toCamera);
    vec3 l = -frame.lightDir.xyz;
    vec3 h = normalize(v + l);
    float nl = max(dot(n, l), 0.0), nv = max(dot(n, v), 1e-4), nh = max(dot(n, h), 0.0), vh = max(dot(v, h), 0.0);
    vec3 f0 = mix(vec3(0.04), albedo, metallic);
    float a = max(roughness * roughness, 2e-3);
    vec3 F = fresnelSchlick(vh, f0);
    vec3 specular = distributionGGX(nh, a) * visibilitySmithGGX(nv, nl, a) * F;
    vec3 diffuse = (1.0 - F) * (1.0 - metallic) * albedo / PI;
    float shadow = nl > 0.0 ? shadowFactor(world, n) : 0.0;
    vec3 direct = (diffuse + specular) * frame.lightColor.rgb * nl * shadow;
    // Hemisphere ambient: diffuse from the sky/ground gradient, a rough specular term from the sky.
    vec3 ambientDiffuse = mix(frame.groundColor.rgb, frame.skyColor.rgb, n.y * 0.5 + 0.5) * albedo * (1.0 - metallic);
    vec3 ambientSpecular = skyRadiance(reflect(-v, n)) * fresnelSchlick(nv, f0) * (1.0 - roughness) * 0.5;
    vec3 color = direct + (ambientDiffuse + ambientSpecular) * frame.skyColor.w;
    // --set debug=shadow: the sun's visibility (the composite divides debug views by the exposure).
    if (frame.debugView == kDebugShadow) color = vec3(shadow * frame.lightColor.w);
    imageStore(outColor, pix, vec4(color, 1.0));
}
