#version 460
#extension GL_GOOGLE_include_directive : require
#include "common/bindings.glsl"
#include "gpu/scene_data.h"

layout(set = 0, binding = 1, scalar) readonly buffer Draws { DrawData draws[]; };
layout(push_constant, scalar) uniform Push { DrawPush pc; };

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec4 inTangent;
layout(location = 3) in vec2 inUv;
layout(location = 4) in vec4 inColor;  // COLOR_0, white without

layout(location = 0) out vec3 vNormal;
layout(location = 1) out vec4 vTangent;
layout(location = 2) out vec2 vUv;
layout(location = 4) out vec4 vColor;

// invariant: the depth pre-pass (no fragment shader, no varyings) must place every vertex exactly where
// the shading pass does, or the two would cover different pixels along silhouettes.
invariant gl_Position;

void main() {
    DrawData d = draws[pc.drawIndex];
    vec4 world = d.world * vec4(inPosition, 1.0);
    vNormal = mat3(d.normalMatrix) * inNormal;
    vTangent = vec4(mat3(d.world) * inTangent.xyz, inTangent.w);
    vUv = inUv;
    vColor = inColor;
    gl_Position = frame.viewProj * world;
}
