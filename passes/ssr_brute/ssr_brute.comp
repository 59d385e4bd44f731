#version 460
#extension GL_GOOGLE_include_directive : require
#include "ssr_common/ssr_pixel.glsl"

// ssr-brute: the reference quality of the SSR family. Visits every pixel the ray's screen-space
// segment crosses (a DDA along the major axis, McGuire & Mara 2014) and compares the range of view
// distances the ray spans over that pixel with the surface there, so no surface thicker than the
// thickness test allows is stepped over.
bool ssrTrace(SsrRay ray, out vec2 hitPixel) {
    hitPixel = vec2(0.0);
    vec2 delta = ray.p1 - ray.p0;
    float span = max(abs(delta.x), abs(delta.y));  // pixels along the major axis
    if (span < 1.0) return false;
    vec2 dp = delta / span;
    float dk = (ray.k1 - ray.k0) / span;
    uint steps = min(uint(span), pc.maxSteps);
    float kBefore = ray.k0 + 0.5 * dk;  // the ray's extent over sample i is [i − ½, i + ½]
    for (uint i = 1u; i <= steps; ++i) {
        float kAfter = ray.k0 + (float(i) + 0.5) * dk;
        float a = 1.0 / kBefore, b = 1.0 / kAfter;
        kBefore = kAfter;
        ivec2 q = ivec2(ray.p0 + dp * float(i));
        float s = ssrSurfaceDistance(q);
        if (max(a, b) >= s && min(a, b) <= s + ssrThicknessAt(s)) {
            hitPixel = vec2(q) + 0.5;
            return true;
        }
    }
    return false;
}
