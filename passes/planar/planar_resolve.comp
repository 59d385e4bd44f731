#version 460
#extension GL_GOOGLE_include_directive : require
#include "common/bindings.glsl"
#include "common/reflection.h"
#include "common/reflector_data.h"
#include "planar/planar.h"

// Planar ground truth, per plane group: copy the mirrored view's lit colour onto the pixels of the
// group's reflectors, and mark whether the reflected point is also visible in the main view (the
// pixels `ppr compare` scores).
layout(local_size_x = kPlanarGroupSize, local_size_y = kPlanarGroupSize) in;
layout(set = 0, binding = 1, scalar) uniform MirrorBlock { FrameConstants mirrored; };
layout(set = 0, binding = 2) uniform sampler2D mirroredColor;
layout(set = 0, binding = 3) uniform sampler2D mirroredDepth;
layout(set = 0, binding = 4) uniform sampler2D mirroredNormal;
layout(set = 0, binding = 5) uniform usampler2D mirroredReflector;
layout(set = 0, binding = 6) uniform sampler2D mainDepth;
layout(set = 0, binding = 7) uniform usampler2D reflectorTex;
layout(set = 0, binding = 8, scalar) readonly buffer Reflectors { ReflectorData reflectors[]; };
layout(set = 0, binding = 9, rgba16f) uniform image2D reflection;
layout(push_constant, scalar) uniform Push { PlanarResolvePush pc; };

// Visible = faces the main camera, lies on screen, and is the surface the main view shows there.
bool visibleInMainView(vec3 p, vec3 n) {
    if (dot(n, frame.cameraPos.xyz - p) <= 0.0) return false;
    vec4 clip = frame.viewProj * vec4(p, 1.0);
    if (clip.w <= 0.0) return false;
    vec2 uv = clip.xy / clip.w * 0.5 + 0.5;
    if (any(lessThan(uv, vec2(0.0))) || any(greaterThanEqual(uv, vec2(1.0)))) return false;
    ivec2 q = ivec2(uv * frame.screenSize);
    float depth = texelFetch(mainDepth, q, 0).r;
    if (depth <= 0.0) return false;
    vec3 seen = worldFromDepth((vec2(q) + 0.5) * frame.invScreenSize, depth);
    float tolerance = kPlanarVisibleTolerance + kPlanarVisibleTolerancePerMetre * distance(frame.cameraPos.xyz, p);
    return distance(seen, p) <= tolerance;
}

void main() {
    ivec2 pix = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(pix, ivec2(frame.screenSize)))) return;
    uint id = texelFetch(reflectorTex, pix, 0).r;
    if (id == 0u || reflectors[id - 1u].planeGroup != pc.planeGroup) return;
    vec3 color = texelFetch(mirroredColor, pix, 0).rgb;
    float depth = texelFetch(mirroredDepth, pix, 0).r;
    float kind = kReflectionOffscreen;  // sky in the reflection has no point to compare
    if (depth > 0.0) {
        vec2 uv = (vec2(pix) + 0.5) * frame.invScreenSize;
        vec4 p = mirrored.invViewProj * vec4(uv * 2.0 - 1.0, depth, 1.0);
        vec3 n = texelFetch(mirroredNormal, pix, 0).xyz;
        if (texelFetch(mirroredReflector, pix, 0).r != 0u) kind = kReflectionSecondary;
        else if (visibleInMainView(p.xyz / p.w, n)) kind = kReflectionHit;
    }
    imageStore(reflection, pix, vec4(color, kind));
}
