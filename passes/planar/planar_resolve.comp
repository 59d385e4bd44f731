#version 460
#extension GL_GOOGLE_include_directive : require
#include "common/bindings.glsl"
#include "common/reflection.h"
#include "common/reflector_data.h"
#include "gpu/scene_data.h"
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
layout(set = 0, binding = 10, rg32f) uniform writeonly image2D reflectedPath;  // planar.h: planar.distance
layout(set = 0, binding = 11) uniform sampler2D mirroredMaterial;  // alpha: the reflected point's motion slot
layout(push_constant, scalar) uniform Push { PlanarResolvePush pc; };

#include "planar/planar_visibility.glsl"
#include "gbuffer/motion_slot.glsl"

// Is the reflected point q, seen in reflector `self`, also reflected to the eye by a parallel shape
// nearer to it (between q and self's plane)? See kPlanarParallelShape.
bool nearerParallelShape(vec3 q, uint self) {
    ReflectorData r = reflectors[self];
    float own = dot(q - r.center, r.normal);
    vec3 eye = frame.cameraPos.xyz;
    for (uint j = 0u; j < pc.reflectorCount; ++j) {
        ReflectorData o = reflectors[j];
        if (j == self || o.orientationGroup != r.orientationGroup) continue;
        float d = dot(q - o.center, o.normal), eyeHeight = dot(eye - o.center, o.normal);
        if (d <= 0.0 || d >= own || eyeHeight <= 0.0) continue;
        vec3 mirrored = q - 2.0 * d * o.normal;
        if (reflectorContains(o, mix(eye, mirrored, eyeHeight / (eyeHeight + d)))) return true;
    }
    return false;
}

void main() {
    ivec2 pix = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(pix, ivec2(frame.screenSize)))) return;
    uint id = texelFetch(reflectorTex, pix, 0).r;
    if (id == 0u || reflectors[id - 1u].planeGroup != pc.planeGroup) return;
    imageStore(reflection, pix, planarSample(pix));
    float depth = texelFetch(mirroredDepth, pix, 0).r;
    vec2 path = vec2(0.0);
    if (depth > 0.0) {
        vec4 p = mirrored.invViewProj * vec4(((vec2(pix) + 0.5) * frame.invScreenSize) * 2.0 - 1.0, depth, 1.0);
        vec3 q = p.xyz / p.w;
        path = vec2(distance(q, mirrored.cameraPos.xyz), pathTag(motionSlotOf(texelFetch(mirroredMaterial, pix, 0)),
                                                                  nearerParallelShape(q, id - 1u) ? kPlanarParallelShape : 0u));
    }
    imageStore(reflectedPath, pix, vec4(path, 0.0, 0.0));
}
