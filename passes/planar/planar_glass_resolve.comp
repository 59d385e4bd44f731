#version 460
#extension GL_GOOGLE_include_directive : require
#include "common/bindings.glsl"
#include "common/reflection.h"
#include "common/reflector_data.h"
#include "glass_forward/glass_forward.h"
#include "planar/planar.h"

// Planar ground truth for glass panels, per plane group: every texel of a panel's atlas region (the
// same layout PPR uses this frame) whose screen position shows the panel — the eye ray meets the
// panel's rectangle, from its reflecting side, in front of the opaque surface there — takes the
// mirrored view's colour at that position. The glass forward pass then blends it exactly as it
// blends PPR's, and `ppr compare` scores the two atlases texel by texel.
layout(local_size_x = kPlanarGroupSize, local_size_y = kPlanarGroupSize) in;
layout(set = 0, binding = 1, scalar) uniform MirrorBlock { FrameConstants mirrored; };
layout(set = 0, binding = 2) uniform sampler2D mirroredColor;
layout(set = 0, binding = 3) uniform sampler2D mirroredDepth;
layout(set = 0, binding = 4) uniform sampler2D mirroredNormal;
layout(set = 0, binding = 5) uniform usampler2D mirroredReflector;
layout(set = 0, binding = 6) uniform sampler2D mainDepth;
layout(set = 0, binding = 7, scalar) readonly buffer Reflectors { ReflectorData reflectors[]; };
layout(set = 0, binding = 8, scalar) readonly buffer Regions { GlassRegionData regions[]; };  // per reflector
layout(set = 0, binding = 9, scalar) readonly buffer RegionList { uint regionReflectors[]; };
layout(set = 0, binding = 10, rgba16f) uniform image2D glassReflection;
layout(push_constant, scalar) uniform Push { PlanarGlassPush pc; };

#include "planar/planar_visibility.glsl"

// Does the eye ray through screen position `q` see panel `r` from its reflecting side, in front of
// the opaque scene?
bool panelShown(ReflectorData r, vec2 q) {
    vec3 eye = frame.cameraPos.xyz;
    if (dot(r.normal, eye - r.center) <= 0.0) return false;
    vec3 dir = worldFromDepth(q * frame.invScreenSize, 1.0) - eye;  // towards the near-plane point
    float denom = dot(dir, r.normal);
    if (denom >= 0.0) return false;
    float t = dot(r.center - eye, r.normal) / denom;
    vec3 hit = eye + dir * t;
    if (!reflectorContains(r, hit)) return false;
    float depth = texelFetch(mainDepth, ivec2(q), 0).r;
    if (depth <= 0.0) return true;  // sky behind the glass
    return distance(hit, eye) < distance(worldFromDepth(q * frame.invScreenSize, depth), eye);
}

void main() {
    ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
    for (uint k = 0u; k < pc.regionCount; ++k) {
        uint panel = regionReflectors[k];
        GlassRegionData region = regions[panel];
        ivec2 lo = ivec2(region.atlasOrigin), hi = lo + ivec2(region.atlasSize);
        if (any(lessThan(texel, lo)) || any(greaterThanEqual(texel, hi))) continue;
        ReflectorData r = reflectors[panel];
        if (r.planeGroup != pc.planeGroup) return;
        vec2 q = region.screenOrigin + (vec2(texel - lo) + 0.5) / region.scale;
        if (any(greaterThanEqual(q, frame.screenSize)) || !panelShown(r, q)) return;
        imageStore(glassReflection, texel, planarSample(ivec2(q)));
        return;
    }
}
