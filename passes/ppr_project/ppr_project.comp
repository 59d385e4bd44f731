#version 460
#extension GL_GOOGLE_include_directive : require
#include "common/bindings.glsl"
#include "common/reflector_data.h"
#include "ppr_common/encoding.h"
#include "ppr_project/ppr_project.h"

// PPR step 2, the projection pass: every pixel finds the reflectors that reflect it and scatters its
// screen-space offset to where it appears in them, keeping the closest with imageAtomicMin.
layout(local_size_x = kPprProjectGroupSize, local_size_y = kPprProjectGroupSize) in;
layout(set = 0, binding = 1) uniform sampler2D depthTex;
layout(set = 0, binding = 2, scalar) readonly buffer Reflectors { ReflectorData reflectors[]; };
layout(set = 0, binding = 3, scalar) readonly buffer Order { uint projectionOrder[]; };
layout(set = 0, binding = 4, r32ui) uniform uimage2D intermediate;
layout(push_constant, scalar) uniform Push { PprProjectPush pc; };

bool insideRectangle(ReflectorData r, vec3 p) {
    vec3 l = p - r.center;
    return abs(dot(l, r.tangent)) <= r.halfExtentU && abs(dot(l, r.bitangent)) <= r.halfExtentV;
}

// Occluding shapes: does the segment eye → hit cross another reflector's rectangle first? Coplanar
// neighbours meet the segment at its end and do not count.
bool occludedByOtherReflector(vec3 eye, vec3 hit, uint self) {
    vec3 d = hit - eye;
    for (uint j = 0u; j < pc.reflectorCount; ++j) {
        if (j == self) continue;
        ReflectorData o = reflectors[j];
        float denom = dot(d, o.normal);
        if (abs(denom) < 1e-8) continue;
        float t = dot(o.center - eye, o.normal) / denom;
        if (t > 1e-4 && t < 1.0 - 1e-4 && insideRectangle(o, eye + d * t)) return true;
    }
    return false;
}

void writeOffset(ivec2 pix, vec3 mirrored) {
    vec4 clip = frame.viewProj * vec4(mirrored, 1.0);
    if (clip.w <= 0.0) return;
    vec2 ndc = clip.xy / clip.w;
    if (any(greaterThanEqual(abs(ndc), vec2(1.0)))) return;
    vec2 target = (ndc * 0.5 + 0.5) * frame.screenSize;
    uint value;
    if (!pprEncode(target - (vec2(pix) + 0.5), value)) return;  // beyond the 12-bit range: dropped, not wrapped
    imageAtomicMin(intermediate, ivec2(target), value);
}

void main() {
    ivec2 pix = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(pix, ivec2(frame.screenSize)))) return;
    float depth = texelFetch(depthTex, pix, 0).r;
    if (depth <= 0.0) return;  // sky: no position to mirror
    vec3 eye = frame.cameraPos.xyz;
    vec3 p = worldFromDepth((vec2(pix) + 0.5) * frame.invScreenSize, depth);
    float above = kPprAboveEpsilon + kPprAboveEpsilonPerMetre * distance(eye, p);

    // Reflectors arrive sorted by orientation. Within one orientation only the shape nearest to the
    // pixel (smallest plane distance) that reflects it is used, so each pixel is written at most once
    // per orientation ("multiple parallel shapes"); different orientations each write their own.
    uint group = 0xFFFFFFFFu;
    uint best = 0xFFFFFFFFu;
    float bestDistance = 0.0;
    vec3 bestMirrored = vec3(0.0), bestHit = vec3(0.0);
    for (uint k = 0u; k <= pc.reflectorCount; ++k) {
        uint i = k < pc.reflectorCount ? projectionOrder[k] : 0u;
        uint g = k < pc.reflectorCount ? reflectors[i].orientationGroup : 0xFFFFFFFEu;
        if (g != group) {
            if (best != 0xFFFFFFFFu && !occludedByOtherReflector(eye, bestHit, best)) writeOffset(pix, bestMirrored);
            group = g;
            best = 0xFFFFFFFFu;
            bestDistance = 3.4e38;
        }
        if (k == pc.reflectorCount) break;
        ReflectorData r = reflectors[i];
        float d = dot(p - r.center, r.normal);
        if (d <= above || d >= bestDistance) continue;  // not above this plane, or a nearer parallel shape won
        float eyeHeight = dot(eye - r.center, r.normal);
        if (eyeHeight <= 0.0) continue;  // the camera sees this reflector from behind
        vec3 mirrored = p - 2.0 * d * r.normal;
        // Ray from the camera to the mirrored point crosses the plane at eyeHeight / (eyeHeight + d).
        vec3 hit = mix(eye, mirrored, eyeHeight / (eyeHeight + d));
        if (!insideRectangle(r, hit)) continue;
        best = i;
        bestDistance = d;
        bestMirrored = mirrored;
        bestHit = hit;
    }
}
