#version 460
#extension GL_GOOGLE_include_directive : require
#include "common/bindings.glsl"
#include "glass_forward/glass_forward.h"
#include "raytrace/raytrace_common.glsl"
#include "raytrace/raster_coverage.glsl"

// The ray-traced reference for glass panes, in this frame's glass atlas layout (the layout PPR and the
// planar reference write, so the glass forward pass blends it and compare scores it unchanged). A
// texel of a pane's region stands for a screen position; where the eye ray through it meets the pane
// from its reflecting side, in front of the opaque surface there, the ray of that pixel's centre is
// reflected about the pane and traced. Other texels keep the atlas's clear value.
layout(local_size_x = kRaytraceGroupSize, local_size_y = kRaytraceGroupSize) in;
layout(constant_id = 0) const bool kRasterCoverage = false;  // rt_coverage=raster, as raytrace_reflect.comp
layout(set = 0, binding = 11, scalar) readonly buffer Regions { GlassRegionData regions[]; };  // per reflector
layout(set = 0, binding = 12, scalar) readonly buffer RegionList { uint regionReflectors[]; };
layout(set = 0, binding = 13, rgba16f) uniform writeonly image2D glassReflection;

// Does the eye ray through screen position q meet pane r from its reflecting side, in front of the
// opaque scene? (The planar reference's rule.)
bool paneShown(ReflectorData r, vec2 q) {
    vec3 eye = frame.cameraPos.xyz;
    if (dot(r.normal, eye - r.center) <= 0.0) return false;
    vec3 hit;
    if (!onPlane(r, eyeRayDir(q), hit) || !reflectorContains(r, hit)) return false;
    float depth = texelFetch(depthTex, ivec2(q), 0).r;
    if (depth <= 0.0) return true;  // sky behind the glass
    return distance(hit, eye) < distance(worldFromDepth(q * frame.invScreenSize, depth), eye);
}

void main() {
    ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
    for (uint k = 0u; k < pc.regionCount; ++k) {
        uint pane = regionReflectors[k];
        GlassRegionData region = regions[pane];
        ivec2 lo = ivec2(region.atlasOrigin), hi = lo + ivec2(region.atlasSize);
        if (any(lessThan(texel, lo)) || any(greaterThanEqual(texel, hi))) continue;
        ReflectorData r = reflectors[pane];
        vec2 q = region.screenOrigin + (vec2(texel - lo) + 0.5) / region.scale;
        if (any(greaterThanEqual(q, frame.screenSize)) || !paneShown(r, q)) return;
        ivec2 pix = ivec2(q);
        vec3 d = eyeRayDir(vec2(pix) + 0.5), origin;
        if (!onPlane(r, d, origin)) return;
        vec3 dir = reflect(d, r.normal);
        float eyeDistance = distance(frame.cameraPos.xyz, origin);
        imageStore(glassReflection, texel, kRasterCoverage
                                               ? rasterCoverageReflection(r, pix, origin, dir, eyeDistance, pc.subpixelBits)
                                               : traceReflection(r, r.normal, pix, origin, dir, eyeDistance));
        return;
    }
}
