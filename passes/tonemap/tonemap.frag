#version 460
#extension GL_GOOGLE_include_directive : require
#include "common/bindings.glsl"

layout(set = 0, binding = 1) uniform sampler2D hdrColor;
layout(location = 0) in vec2 vUv;
layout(location = 0) out vec4 outColor;

// Narkowicz's ACES filmic fit: cheap, neutral enough for comparing techniques.
vec3 aces(vec3 x) { return clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0); }
vec3 linearToSrgb(vec3 c) {
    return mix(c * 12.92, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(vec3(0.0031308), c));
}

void main() {
    vec3 hdr = texelFetch(hdrColor, ivec2(gl_FragCoord.xy), 0).rgb;
    // The attachment is UNORM: encode sRGB here so captures and the swapchain get identical bytes.
    outColor = vec4(linearToSrgb(aces(hdr * frame.lightColor.w)), 1.0);
}
