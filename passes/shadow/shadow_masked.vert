#version 460
#extension GL_GOOGLE_include_directive : require
#include "common/bindings.glsl"
#include "gpu/scene_data.h"

// The shadow map's alpha-masked draws (glTF alphaMode MASK): as shadow.vert, plus what
// shadow_masked.frag needs to cut them out.
layout(set = 0, binding = 1, scalar) readonly buffer Draws { DrawData draws[]; };
layout(push_constant, scalar) uniform Push { DrawPush pc; };
layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;   // bound with the full vertex layout; unused here
layout(location = 2) in vec4 inTangent;  // unused
layout(location = 3) in vec2 inUv;
layout(location = 4) in vec4 inColor;

layout(location = 0) out vec2 vUv;
layout(location = 2) out float vAlpha;  // COLOR_0's alpha

void main() {
    vUv = inUv;
    vAlpha = inColor.a;
    gl_Position = frame.lightViewProj * (draws[pc.drawIndex].world * vec4(inPosition, 1.0));
}
