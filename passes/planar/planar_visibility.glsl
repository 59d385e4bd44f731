// The planar ground truth at one pixel of a mirrored view, and what it scores: a reflected point that
// the main view also shows (so a screen-space technique could have it). The includer binds
// `mainDepth` (the main view's depth), the mirrored view's `mirrored` constants and its
// `mirroredColor`, `mirroredDepth`, `mirroredNormal` and `mirroredReflector` images.
#include "planar/planar.h"

#include "planar/main_view.glsl"

// The mirrored view's colour at a pixel and its common/reflection.h kind.
vec4 planarSample(ivec2 pix) {
    vec3 color = texelFetch(mirroredColor, pix, 0).rgb;
    float depth = texelFetch(mirroredDepth, pix, 0).r;
    float kind = kReflectionOffscreen;  // sky in the reflection has no point to compare
    if (depth > 0.0) {
        vec2 uv = (vec2(pix) + 0.5) * frame.invScreenSize;
        vec4 p = mirrored.invViewProj * vec4(uv * 2.0 - 1.0, depth, 1.0);
        vec3 n = texelFetch(mirroredNormal, pix, 0).xyz;
        if (texelFetch(mirroredReflector, pix, 0).r != 0u) kind = kReflectionSecondary;
        else if (visibleInMainView(mainDepth, p.xyz / p.w, n)) kind = kReflectionHit;
    }
    return vec4(color, kind);
}
