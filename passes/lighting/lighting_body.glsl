// The lighting pass, compiled twice: lighting.comp adds the G-buffer's emissive target
// (PPR_LIGHTING_EMISSIVE), lighting_no_emissive.comp is for a G-buffer without one (LightingPass).
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
#ifdef PPR_LIGHTING_EMISSIVE
layout(set = 0, binding = 7) uniform sampler2D emissiveTex;  // the G-buffer's emissive target
#endif

#include "lighting/shade.glsl"

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
    float shadow;
    vec3 color = shadeSurface(world, n, v, albedo, roughness, metallic, shadow);
#ifdef PPR_LIGHTING_EMISSIVE
    color += texelFetch(emissiveTex, pix, 0).rgb;
#endif
    // --set debug=shadow: the sun's visibility (the composite divides debug views by the exposure).
    if (frame.debugView == kDebugShadow) color = vec3(shadow * frame.lightColor.w);
    imageStore(outColor, pix, vec4(color, 1.0));
}
