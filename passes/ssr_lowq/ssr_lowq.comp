#version 460
#extension GL_GOOGLE_include_directive : require
#include "ssr_common/ssr_pixel.glsl"

// ssr-lowq: the cheap end of the SSR family. The same march as ssr-brute (along the major axis of
// the screen-space segment, k = 1/distance affine), but one sample every kSsrLowqStride pixels; where
// the ray goes from in front of the surface to behind it, a binary search of that segment finds the
// crossing to pixel precision (log2 of the stride halvings). Anything thinner than the stride that the
// ray passes behind and comes out of between two samples is missed: that is the price of the speed.

// Where the ray is `i` pixels along the major axis from p0 (the pixel under it, and its distance).
struct LowqSample {
    ivec2 pix;
    float ray;      // view distance of the ray
    float surface;  // view distance of the surface seen at `pix`
};

LowqSample lowqSample(SsrRay ray, vec2 dp, float dk, float i) {
    LowqSample s;
    s.pix = ivec2(ray.p0 + dp * i);  // the integer pixel under the sample, as ssr-brute reads it
    s.ray = 1.0 / (ray.k0 + dk * i);
    s.surface = ssrSurfaceDistance(s.pix);
    return s;
}

bool lowqBehind(LowqSample s) { return s.ray >= s.surface; }
bool lowqHits(LowqSample s) { return lowqBehind(s) && s.ray <= s.surface + ssrThicknessAt(s.surface); }

// ssr-brute's test for the pixel under sample i: does the ray's extent over it ([i − ½, i + ½] along
// the major axis) overlap [surface, surface + thickness]? A ray receding from the camera can move more
// than the thickness in depth within one pixel, so testing the centre alone would miss it.
bool lowqPixelHits(SsrRay ray, vec2 dp, float dk, float i) {
    ivec2 pix = ivec2(ray.p0 + dp * i);
    float a = 1.0 / (ray.k0 + dk * (i - 0.5)), b = 1.0 / (ray.k0 + dk * (i + 0.5));
    float s = ssrSurfaceDistance(pix);
    return max(a, b) >= s && min(a, b) <= s + ssrThicknessAt(s);
}

bool ssrTrace(SsrRay ray, out vec2 hitPixel) {
    hitPixel = vec2(0.0);
    vec2 delta = ray.p1 - ray.p0;
    float span = max(abs(delta.x), abs(delta.y));  // pixels along the major axis
    if (span < 1.0) return false;
    vec2 dp = delta / span;
    float dk = (ray.k1 - ray.k0) / span;
    // The origin is lifted off its surface, so the march starts in front of the scene.
    float prev = 0.0;
    bool prevFront = true;
    for (uint n = 0u; n < pc.maxSteps && prev < span; ++n) {
        // The last stride is cut at the segment's end so its far part is not skipped.
        float cur = min(prev + kSsrLowqStride, span);
        LowqSample s = lowqSample(ray, dp, dk, cur);
        bool behind = lowqBehind(s), hits = lowqHits(s);
        // Refine a front-to-behind segment even when the sample is far behind: a ray that crosses a
        // surface travels up to a stride past it, usually beyond the thickness, and the crossing
        // itself is the hit. After an earlier sample behind (no front endpoint), search for the first
        // point within the thickness instead.
        if (behind && (prevFront || hits)) {
            float lo = prev, hi = cur;  // invariant: the predicate fails at lo and holds at hi
            for (uint j = 0u; j < kSsrLowqRefineSteps; ++j) {
                float mid = 0.5 * (lo + hi);
                LowqSample m = lowqSample(ray, dp, dk, mid);
                if (prevFront ? lowqBehind(m) : lowqHits(m)) {
                    hi = mid;
                } else {
                    lo = mid;
                }
            }
            // The search ends one pixel wide: the crossing is over pixel lo or hi, accepted with
            // ssr-brute's per-pixel test. If it fails, the crossing is the edge of an object the ray
            // passed behind; then the stride sample itself, if it hit, is the best answer we have.
            for (int e = 0; e < 2; ++e) {
                float i = e == 0 ? lo : hi;
                if (i > 0.0 && lowqPixelHits(ray, dp, dk, i)) {
                    hitPixel = vec2(ivec2(ray.p0 + dp * i)) + 0.5;
                    return true;
                }
            }
            if (hits) {
                hitPixel = vec2(s.pix) + 0.5;
                return true;
            }
        }
        // No hit: in front, or behind beyond the thickness (the ray passed behind an object): march on.
        prevFront = !behind;
        prev = cur;
    }
    return false;
}
