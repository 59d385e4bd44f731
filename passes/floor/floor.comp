#version 460
#extension GL_GOOGLE_include_directive : require
#include "common/bindings.glsl"
#include "common/reflection.h"

// The cost floor of any screen-space reflection: read depth and the lit scene once per pixel, write
// one rgba16f value. Draws no reflection (alpha kReflectionNone), so the frame looks like `none`.
layout(local_size_x = 16, local_size_y = 16) in;
layout(set = 0, binding = 1) uniform sampler2D depthTex;
layout(set = 0, binding = 2) uniform sampler2D sceneColor;
layout(set = 0, binding = 3, rgba16f) uniform writeonly image2D outReflection;

void main() {
    ivec2 pix = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(pix, ivec2(frame.screenSize)))) return;
    float depth = texelFetch(depthTex, pix, 0).r;
    vec3 color = texelFetch(sceneColor, pix, 0).rgb;
    // Both reads feed the value written, so neither can be optimised away.
    imageStore(outReflection, pix, vec4(depth > 0.0 ? color : vec3(0.0), kReflectionNone));
}
