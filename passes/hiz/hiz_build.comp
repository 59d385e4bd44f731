#version 460
#extension GL_GOOGLE_include_directive : require
#include "common/bindings.glsl"
#include "hiz/hiz.h"
#include "hiz/hiz_level0.glsl"

// One level (≥ 1) of the depth hierarchy (hiz.h): level 1 the minimum of each 2×2 quad of the depth
// buffer (as 1 − depth; beyond the screen, empty), every other level the minimum of the 2×2 texels
// below it. Level 0 is the depth buffer itself and is not built.
layout(local_size_x = kHizGroupSize, local_size_y = kHizGroupSize) in;
layout(set = 0, binding = 1) uniform sampler2D depthTex;
layout(set = 0, binding = 2, r32f) uniform image2D atlas;
layout(push_constant, scalar) uniform Push { HizBuildPush pc; };

void main() {
    ivec2 c = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(uvec2(c), pc.dstSize))) return;
    ivec2 p = 2 * c;
    float v;
    if (pc.level == 1u) {
        if (all(lessThan(p + 1, ivec2(frame.screenSize)))) {
            // The whole quad on screen: one gather (the sample point is the quad's shared corner).
            vec4 d = textureGather(depthTex, vec2(p + 1) * frame.invScreenSize, 0);
            v = min(min(hizFromReverseZ(d.x), hizFromReverseZ(d.y)), min(hizFromReverseZ(d.z), hizFromReverseZ(d.w)));
        } else {
            v = min(min(hizLevel0(depthTex, p), hizLevel0(depthTex, p + ivec2(1, 0))),
                    min(hizLevel0(depthTex, p + ivec2(0, 1)), hizLevel0(depthTex, p + ivec2(1, 1))));
        }
    } else {
        ivec2 s = pc.srcOrigin + p;
        v = min(min(imageLoad(atlas, s).r, imageLoad(atlas, s + ivec2(1, 0)).r),
                min(imageLoad(atlas, s + ivec2(0, 1)).r, imageLoad(atlas, s + ivec2(1, 1)).r));
    }
    imageStore(atlas, pc.dstOrigin + c, vec4(v));
}
