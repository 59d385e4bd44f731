#version 460
#extension GL_GOOGLE_include_directive : require
#include "common/bindings.glsl"
#include "raytrace/raytrace_common.glsl"
#include "raytrace/raster_coverage.glsl"

// The ray-traced reference on screen: every reflector pixel (G-buffer reflector id != 0, the pixels
// the planar reference resolves) traces its mirror ray and writes what it sees with its kind
// (raytrace_common.glsl); every other pixel gets "no reflection".
layout(local_size_x = kRaytraceGroupSize, local_size_y = kRaytraceGroupSize) in;
// --set rt_coverage=raster: a pipeline of its own, so that the exact one carries none of its code.
layout(constant_id = 0) const bool kRasterCoverage = false;
layout(set = 0, binding = 11) uniform sampler2D normalTex;
layout(set = 0, binding = 12) uniform usampler2D reflectorTex;
layout(set = 0, binding = 13, rgba16f) uniform writeonly image2D reflection;
layout(set = 0, binding = 14, rg32f) uniform writeonly image2D pathLength;  // kRaytraceWriteDistance: common/reflection.h, eye → reflector → hit

// The mirror ray of reflector pixel `pix` (reflector index + 1 `id`), false when the planar
// reference has no reflection there (the camera sees the plane from behind, or the pixel's eye ray
// does not meet it).
//
// Flat reflectors (normalmap=off): the ray starts where the eye ray meets the reflector's plane and is
// reflected about the plane's normal, exactly the ray of the planar reference's mirrored camera. With
// normal maps on, it starts at the G-buffer's point and is reflected about its normal-mapped normal
// (a ray that would dive under the plane is mirrored back above it).
bool reflectorRay(ivec2 pix, uint id, out ReflectorData r, out vec3 n, out vec3 origin, out vec3 dir) {
    vec3 eye = frame.cameraPos.xyz;
    r = reflectors[id - 1u];
    vec3 d = eyeRayDir(vec2(pix) + 0.5);
    n = r.normal;
    dir = d;
    if (dot(eye - r.center, r.normal) <= 0.0 || !onPlane(r, d, origin)) return false;
    if ((pc.flags & kRaytraceNormalMapped) != 0u) {
        float depth = texelFetch(depthTex, pix, 0).r;
        origin = worldOfPixel(pix, depth);
        n = normalize(texelFetch(normalTex, pix, 0).xyz);
        if (dot(n, d) >= 0.0) n = r.normal;  // a normal facing away from the eye: the plane's
    }
    dir = reflect(d, n);
    float rise = dot(dir, r.normal);
    if (rise <= 1e-4) dir = normalize(dir - r.normal * (2.0 * rise - 1e-4));
    return true;
}

void main() {
    ivec2 pix = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(pix, ivec2(frame.screenSize)))) return;
    uint id = texelFetch(reflectorTex, pix, 0).r;
    vec4 result = vec4(0.0, 0.0, 0.0, kReflectionNone);
    ReflectorData r;
    vec3 n, origin, dir;
    vec2 path = vec2(0.0);  // reflected-path image (common/reflection.h): length, the hit's motion slot
    if (id != 0u && reflectorRay(pix, id, r, n, origin, dir)) {
        float eyeDistance = distance(frame.cameraPos.xyz, origin);
        bool raster = kRasterCoverage && (pc.flags & kRaytraceNormalMapped) == 0u;
        result = raster ? rasterCoverageReflection(r, pix, origin, dir, eyeDistance, pc.subpixelBits)
                        : traceReflection(r, n, pix, origin, dir, eyeDistance);
        if (traceHitT > 0.0) path = vec2(eyeDistance + traceHitT, pathTag(traceHitSlot, 0u));
    }
    imageStore(reflection, pix, result);
    if ((pc.flags & kRaytraceWriteDistance) != 0u) imageStore(pathLength, pix, vec4(path, 0.0, 0.0));
}
