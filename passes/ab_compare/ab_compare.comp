#version 460
#extension GL_GOOGLE_include_directive : require
#include "common/bindings.glsl"
#include "common/reflection.h"
#include "ab_compare/ab_compare.h"
#include "common/heat_map.h"
#include "tonemap/tonemap.h"

// A/B against the planar ground truth. Split: one reflection image, the technique's on the left of
// the split line and the reference's on the right (a 1-px white line between), composited as usual.
// Heat: over the composited frame, the display-space error of the technique's reflection on the
// pixels the reference scores (common/heat_map.h, as `ppr compare`),
// grey on reflector pixels it does not score, the frame dimmed elsewhere.
layout(local_size_x = 16, local_size_y = 16) in;
layout(set = 0, binding = 1) uniform sampler2D techniqueTex;
layout(set = 0, binding = 2) uniform sampler2D referenceTex;
layout(set = 0, binding = 3, rgba16f) uniform image2D target;  // split: the merged reflection; heat: the HDR frame
layout(push_constant, scalar) uniform Push { AbComparePush pc; };

void main() {
    ivec2 pix = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(pix, ivec2(frame.screenSize)))) return;
    vec4 a = texelFetch(techniqueTex, pix, 0), b = texelFetch(referenceTex, pix, 0);
    if (pc.mode == kAbSplit) {
        vec4 v = float(pix.x) < pc.splitX ? a : b;
        if (abs(float(pix.x) + 0.5 - pc.splitX) < 0.5) v = vec4(vec3(4.0), kReflectionHit);
        imageStore(target, pix, v);
        return;
    }
    float exposure = frame.lightColor.w;
    vec3 display;
    if (b.a == kReflectionHit) {
        vec3 d = abs(displayFromRadiance(a.rgb, exposure) - displayFromRadiance(b.rgb, exposure));
        display = errorHeatColor(max(d.r, max(d.g, d.b)));
    } else if (b.a > 0.0) {
        display = vec3(0.25);
    } else {
        display = displayFromRadiance(imageLoad(target, pix).rgb, exposure) * 0.25;
    }
    imageStore(target, pix, vec4(radianceFromDisplay(display, exposure), 1.0));
}
