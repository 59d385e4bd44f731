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

vec3 worldAt(ivec2 q) {
    q = clamp(q, ivec2(0), ivec2(frame.screenSize) - 1);
    return worldOfPixel(q, texelFetch(depthTex, q, 0).r);
}

// p(q + step) − p(q) or p(q) − p(q − step), whichever neighbour lies nearer in depth.
vec3 neighbourDelta(ivec2 q, ivec2 step, vec3 p) {
    vec3 ahead = worldAt(q + step) - p, behind = p - worldAt(q - step);
    return dot(ahead, ahead) <= dot(behind, behind) ? ahead : behind;
}

void main() {
    PickResult r;
    r.position = vec4(0.0);
    r.normal = vec4(0.0);
    r.reflectorId = 0u;
    r.pad0 = r.pad1 = r.pad2 = 0u;
    if (all(greaterThanEqual(pc.pixel, ivec2(0))) && all(lessThan(pc.pixel, ivec2(frame.screenSize)))) {
        float depth = texelFetch(depthTex, pc.pixel, 0).r;
        if (depth > 0.0) {
            vec3 p = worldAt(pc.pixel);
            r.position = vec4(p, 1.0);
            // The surface's geometric normal from neighbouring depths (the G-buffer normal is normal-mapped:
            // a reflector snapped onto a tiled floor must lie in the floor, not in a bump's tangent plane).
            // Per axis, the neighbour nearer in depth, so an edge beside the pixel does not bend it.
            vec3 dx = neighbourDelta(pc.pixel, ivec2(1, 0), p), dy = neighbourDelta(pc.pixel, ivec2(0, 1), p);
            vec3 n = cross(dy, dx);
            vec3 shading = normalize(texelFetch(normalTex, pc.pixel, 0).xyz);
            n = length(n) > 1e-12 ? normalize(n) : shading;
            r.normal = vec4(dot(n, shading) < 0.0 ? -n : n, 0.0);
            r.reflectorId = texelFetch(reflectorTex, pc.pixel, 0).r;
        }
    }
    result = r;
}
