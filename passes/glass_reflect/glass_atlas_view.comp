#version 460
#extension GL_GOOGLE_include_directive : require
#include "common/bindings.glsl"
#include "glass_reflect/glass_reflect.h"

// --set debug=atlas: the glass reflection atlas fitted to the screen height, left-aligned: resolved
// texels in their colour, texels without a reflection (outside the regions, or no data) near black.
// The rest of the screen keeps the frame, dimmed.
layout(local_size_x = kGlassReflectGroupSize, local_size_y = kGlassReflectGroupSize) in;
layout(set = 0, binding = 1) uniform sampler2D reflectionAtlas;
layout(set = 0, binding = 2, rgba16f) uniform image2D color;

void main() {
    ivec2 pix = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(pix, ivec2(frame.screenSize)))) return;
    float side = frame.screenSize.y;
    vec3 c = imageLoad(color, pix).rgb * 0.25;
    if (float(pix.x) < side) {
        vec2 uv = (vec2(pix) + 0.5) / side;
        vec4 texel = texelFetch(reflectionAtlas, ivec2(uv * vec2(textureSize(reflectionAtlas, 0))), 0);
        c = texel.a > 0.0 ? texel.rgb : vec3(0.02);
    }
    imageStore(color, pix, vec4(c, 1.0));
}
