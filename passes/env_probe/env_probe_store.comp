#version 460
#extension GL_GOOGLE_include_directive : require
#include "common/bindings.glsl"
#include "env_probe/env_probe.h"

// One face of the reflection probe: every cube texel takes the texel of the face's 90° render that
// its direction projects to. Going through the face's own view-projection (frame constants at
// binding 0) rather than assuming an orientation keeps the cube's face conventions in one place
// (cubeDirection) whatever way the render camera is rolled or handed. Alpha is the distance from the
// probe's centre to what it saw there, 0 for sky (common/environment.glsl marches through it).
layout(local_size_x = kEnvProbeGroupSize, local_size_y = kEnvProbeGroupSize) in;
layout(set = 0, binding = 1) uniform sampler2D litColor;
layout(set = 0, binding = 2) uniform sampler2D depthTex;  // reverse-Z: 0 = sky
layout(set = 0, binding = 3, rgba16f) uniform writeonly image2DArray probe;
layout(push_constant, scalar) uniform Push { EnvProbeStorePush pc; };

// Direction of cube texel coordinates st in [0, 1]² of `face` (the Vulkan spec's cube face selection
// table, inverted).
vec3 cubeDirection(uint face, vec2 st) {
    vec2 c = st * 2.0 - 1.0;
    switch (face) {
        case 0u: return vec3(1.0, -c.y, -c.x);
        case 1u: return vec3(-1.0, -c.y, c.x);
        case 2u: return vec3(c.x, 1.0, c.y);
        case 3u: return vec3(c.x, -1.0, -c.y);
        case 4u: return vec3(c.x, -c.y, 1.0);
        default: return vec3(-c.x, -c.y, -1.0);
    }
}

void main() {
    ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(texel, ivec2(pc.size)))) return;
    vec3 dir = cubeDirection(pc.face, (vec2(texel) + 0.5) / float(pc.size));
    vec4 h = frame.viewProj * vec4(frame.cameraPos.xyz + dir, 1.0);
    ivec2 src = clamp(ivec2(floor(pixelFromClip(h))), ivec2(0), ivec2(frame.screenSize) - 1);
    float depth = texelFetch(depthTex, src, 0).r;
    float distance = depth > 0.0 ? length(worldOfPixel(src, depth) - frame.cameraPos.xyz) : 0.0;
    imageStore(probe, ivec3(texel, int(pc.face)), vec4(texelFetch(litColor, src, 0).rgb, distance));
}
