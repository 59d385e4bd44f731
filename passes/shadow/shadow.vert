#version 460
#extension GL_GOOGLE_include_directive : require
#include "common/bindings.glsl"
#include "gpu/scene_data.h"

layout(set = 0, binding = 1, scalar) readonly buffer Draws { DrawData draws[]; };
layout(push_constant, scalar) uniform Push { DrawPush pc; };
layout(location = 0) in vec3 inPosition;

void main() {
    gl_Position = frame.lightViewProj * (draws[pc.drawIndex].world * vec4(inPosition, 1.0));
}
