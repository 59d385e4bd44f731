#version 460
#extension GL_GOOGLE_include_directive : require
#include "ssr_common/ssr_pixel.glsl"
#include "ssr_common/ssr_cells.glsl"

// ssr-brute: the reference quality of the SSR family. Visits every pixel the ray's screen-space
// segment crosses, in order (McGuire & Mara 2014 march at pixel granularity, here as an exact cell
// walk so no pixel the ray touches is skipped), and compares the range of view distances the ray
// spans inside that pixel with the surface there. ssr-hiz walks the same pixels where the depth
// hierarchy cannot rule them out, so it finds the same first hit with fewer steps.
bool ssrTrace(SsrRay ray, out vec2 hitPixel) {
    hitPixel = vec2(0.0);
    SsrSegment seg = ssrSegment(ray);
    float slack = ssrSlack(seg);
    float dk = ray.k1 - ray.k0;
    // The pixel the ray starts in holds its own surface: leave it before testing anything.
    float t = ssrCellExit(seg, ssrCellAt(seg, 0.0, 1.0), 1.0);
    for (uint i = 0u; i < pc.maxSteps && t < 1.0; ++i) {
        vec2 cell = ssrCellAt(seg, t, 1.0);
        float tExit = ssrCellExit(seg, cell, 1.0);
        // k = 1/distance is monotonic along the segment: the ray's extent in this pixel (and the
        // slack past it, as in ssr-hiz) lies between its two ends.
        float kIn = ray.k0 + t * dk, kOut = ray.k0 + min(tExit + slack, 1.0) * dk;
        float nearest = 1.0 / max(kIn, kOut), farthest = 1.0 / min(kIn, kOut);
        float s = ssrSurfaceDistance(ivec2(cell));
        if (farthest >= s && nearest <= s + ssrThicknessAt(s)) {
            hitPixel = cell + 0.5;
            return true;
        }
        t = tExit;
    }
    return false;
}
