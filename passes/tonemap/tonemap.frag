#version 460
#extension GL_GOOGLE_include_directive : require
#include "common/bindings.glsl"
#include "tonemap/tonemap.h"

layout(set = 0, binding = 1) uniform sampler2D hdrColor;
layout(location = 0) in vec2 vUv;
layout(location = 0) out vec4 outColor;

void main() {
    vec3 hdr = texelFetch(hdrColor, ivec2(gl_FragCoord.xy), 0).rgb;
    // The attachment is UNORM: encode sRGB here so captures and the swapchain get identical bytes.
    outColor = vec4(displayFromRadiance(hdr, frame.lightColor.w), 1.0);
}
