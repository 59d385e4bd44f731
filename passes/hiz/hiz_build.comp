#version 460
#extension GL_GOOGLE_include_directive : require
#include "common/bindings.glsl"
#include "hiz/hiz.h"

// One level of the depth hierarchy (hiz.h): level 0 from the depth buffer (padding = empty), every
// other level the minimum of the 2×2 texels below it.
layout(local_size_x = kHizGroupSize, local_size_y = kHizGroupSize) in;
layout(set = 0, binding = 1) uniform sampler2D depthTex;
layout(set = 0, binding = 2, r32f) uniform image2D atlas;
layout(push_constant, scalar) uniform Push { HizBuildPush pc; };

void main() {
    ivec2 c = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(uvec2(c), pc.dstSize))) return;
    float v;
    if (pc.level == 0u) {
        v = all(lessThan(c, ivec2(frame.screenSize))) ? hizFromReverseZ(texelFetch(depthTex, c, 0).r) : kHizEmpty;
    } else {
        ivec2 s = pc.srcOrigin + 2 * c;
        v = min(min(imageLoad(atlas, s).r, imageLoad(atlas, s + ivec2(1, 0)).r),
                min(imageLoad(atlas, s + ivec2(0, 1)).r, imageLoad(atlas, s + ivec2(1, 1)).r));
    }
    imageStore(atlas, pc.dstOrigin + c, vec4(v));
}
