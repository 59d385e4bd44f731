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

#include "planar/planar_visibility.glsl"

void main() {
    ivec2 pix = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(pix, ivec2(frame.screenSize)))) return;
    uint id = texelFetch(reflectorTex, pix, 0).r;
    if (id == 0u || reflectors[id - 1u].planeGroup != pc.planeGroup) return;
    imageStore(reflection, pix, planarSample(pix));
}
