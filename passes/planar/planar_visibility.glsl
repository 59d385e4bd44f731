// The planar ground truth at one pixel of a mirrored view, and what it scores: a reflected point that
// the main view also shows (so a screen-space technique could have it). The includer binds
// `mainDepth` (the main view's depth), the mirrored view's `mirrored` constants and its
// `mirroredColor`, `mirroredDepth`, `mirroredNormal` and `mirroredReflector` images.
#include "planar/planar.h"

// Visible = faces the main camera, lies on screen, and is the surface the main view shows there.
bool visibleInMainView(vec3 p, vec3 n) {
    if (dot(n, frame.cameraPos.xyz - p) <= 0.0) return false;
    vec4 clip = frame.viewProj * vec4(p, 1.0);
    if (clip.w <= 0.0) return false;
    vec2 uv = clip.xy / clip.w * 0.5 + 0.5;
    if (any(lessThan(uv, vec2(0.0))) || any(greaterThanEqual(uv, vec2(1.0)))) return false;
    ivec2 q = ivec2(uv * frame.screenSize);
    float depth = texelFetch(mainDepth, q, 0).r;
    if (depth <= 0.0) return false;
    vec3 seen = worldFromDepth((vec2(q) + 0.5) * frame.invScreenSize, depth);
    float tolerance = kPlanarVisibleTolerance + kPlanarVisibleTolerancePerMetre * distance(frame.cameraPos.xyz, p);
    return distance(seen, p) <= tolerance;
}

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
        else if (visibleInMainView(p.xyz / p.w, n)) kind = kReflectionHit;
    }
    return vec4(color, kind);
}
