#version 460
#extension GL_GOOGLE_include_directive : require
#include "common/bindings.glsl"
#include "lighting/lighting.h"

// Composite: the point where reflection techniques are blended onto the lit scene (later issues),
// and where the G-buffer debug views are drawn (--set debug=...).
layout(local_size_x = kLightingGroupSize, local_size_y = kLightingGroupSize) in;
layout(set = 0, binding = 1) uniform sampler2D sceneColor;
layout(set = 0, binding = 2) uniform sampler2D depthTex;
layout(set = 0, binding = 3) uniform sampler2D normalTex;
layout(set = 0, binding = 4) uniform sampler2D albedoTex;
layout(set = 0, binding = 5) uniform sampler2D materialTex;
layout(set = 0, binding = 6) uniform usampler2D reflectorTex;
layout(set = 0, binding = 7, rgba16f) uniform writeonly image2D outColor;

vec3 idColor(uint id) {
    uint h = id * 2654435761u;
    return vec3((h >> 8) & 255u, (h >> 16) & 255u, (h >> 24) & 255u) / 255.0;
}

void main() {
    ivec2 pix = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(pix, ivec2(frame.screenSize)))) return;
    vec3 c = texelFetch(sceneColor, pix, 0).rgb;
    uint view = frame.debugView;
    if (view == kDebugAlbedo) c = texelFetch(albedoTex, pix, 0).rgb;
    else if (view == kDebugNormals) c = texelFetch(normalTex, pix, 0).xyz * 0.5 + 0.5;
    else if (view == kDebugRoughness) c = texelFetch(materialTex, pix, 0).rgb;
    else if (view == kDebugDepth) c = vec3(pow(texelFetch(depthTex, pix, 0).r, 0.25));
    else if (view == kDebugReflectors) {
        uint id = texelFetch(reflectorTex, pix, 0).r;
        if (id != 0u) c = mix(c, idColor(id), 0.6);
    }
    // Debug views are shown without tonemapping curves distorting them too much: divide by exposure.
    if (view != kDebugNone && view != kDebugReflectors) c /= max(frame.lightColor.w, 1e-4);
    imageStore(outColor, pix, vec4(c, 1.0));
}
