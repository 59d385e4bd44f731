#version 460
#extension GL_GOOGLE_include_directive : require
#include "common/bindings.glsl"
#include "tonemap/tonemap.h"

layout(set = 0, binding = 1) uniform sampler2D hdrColor;  // bilinear when upscaling, else point
layout(push_constant, scalar) uniform Push { TonemapPush pc; };
layout(location = 0) in vec2 vUv;
layout(location = 0) out vec4 outColor;

void main() {
    vec3 hdr = pc.upscale != 0u ? textureLod(hdrColor, gl_FragCoord.xy * pc.invTargetSize, 0.0).rgb
                                : texelFetch(hdrColor, ivec2(gl_FragCoord.xy), 0).rgb;
    // The attachment is UNORM: encode sRGB here so captures and the swapchain get identical bytes.
    outColor = vec4(displayFromRadiance(hdr, frame.lightColor.w), 1.0);
}
