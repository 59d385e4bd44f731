#version 460
#extension GL_GOOGLE_include_directive : require
#include "common/bindings.glsl"
#include "pick/pick.h"

// One thread: the G-buffer under the cursor, for the reflector editor (select, snap, auto-fit).
layout(local_size_x = 1) in;
layout(set = 0, binding = 1) uniform sampler2D depthTex;
layout(set = 0, binding = 2) uniform sampler2D normalTex;
layout(set = 0, binding = 3) uniform usampler2D reflectorTex;
layout(set = 0, binding = 4, scalar) writeonly buffer Result { PickResult result; };
layout(push_constant, scalar) uniform Push { PickPush pc; };

void main() {
    PickResult r;
    r.position = vec4(0.0);
    r.normal = vec4(0.0);
    r.reflectorId = 0u;
    r.pad0 = r.pad1 = r.pad2 = 0u;
    if (all(greaterThanEqual(pc.pixel, ivec2(0))) && all(lessThan(pc.pixel, ivec2(frame.screenSize)))) {
        float depth = texelFetch(depthTex, pc.pixel, 0).r;
        if (depth > 0.0) {
            r.position = vec4(worldFromDepth((vec2(pc.pixel) + 0.5) * frame.invScreenSize, depth), 1.0);
            r.normal = vec4(normalize(texelFetch(normalTex, pc.pixel, 0).xyz), 0.0);
            r.reflectorId = texelFetch(reflectorTex, pc.pixel, 0).r;
        }
    }
    result = r;
}
