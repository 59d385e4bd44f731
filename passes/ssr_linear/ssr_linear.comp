#version 460
#extension GL_GOOGLE_include_directive : require
#include "ssr_common/ssr_pixel.glsl"

// ssr-linear: the write-up's method (zznewclear13, "Screen Space Reflection", 2024). The end point is
// clipped to the view frustum in view space, then k = 1/w and the screen position p are interpolated
// linearly between the two projected ends in a fixed number of steps, with a thickness test, a binary
// search of the step that hit, and "potential hits": where the ray dived behind an object deeper than
// the thickness right after being in front, the shallowest such step is searched as a fallback.
// The write-up also interpolates q = clip-space z; here clip z is the constant near plane (reverse-Z,
// infinite far: clip = (…, near, distance)), so the ray's depth q.z·k = near·k and its view distance
// is 1/k: interpolating k alone is the same thing.
// Also done here, as the write-up left open: the step count follows the segment's length on screen.

// Clips the segment from → to (view space, inside the frustum at `from`) to the frustum: the four
// side planes |x| <= sx·d, |y| <= sy·d (d = −z, the view distance) and the near plane d >= near.
// The projection has an infinite far plane, so there is no far clip. Returns the clipped end.
vec3 linearFrustumClip(vec3 from, vec3 to) {
    vec2 slope = vec2(1.0 / frame.proj[0][0], 1.0 / abs(frame.proj[1][1]));
    // Signed distance to each plane as f(point) <= 0 inside; f is affine along the segment.
    float t = 1.0;
    for (int i = 0; i < 5; ++i) {
        float f0, f1;
        if (i < 4) {
            int axis = i >> 1;
            float sgn = (i & 1) == 0 ? 1.0 : -1.0;
            f0 = sgn * from[axis] - slope[axis] * -from.z;
            f1 = sgn * to[axis] - slope[axis] * -to.z;
        } else {
            f0 = ssrNear() + from.z;  // near − d
            f1 = ssrNear() + to.z;
        }
        // Leaves through this plane: cut where f crosses 0 (a start a hair outside cuts at 0).
        if (f1 > 0.0) t = min(t, f0 < 0.0 ? f0 / (f0 - f1) : 0.0);
    }
    return mix(from, to, t);
}

// One point of the march at fraction w of the segment.
struct LinearSample {
    vec2 p;         // pixels
    ivec2 pix;      // the integer pixel the depth is read at (point sampling, as the write-up)
    float surface;  // view distance of the surface at `pix`
    float diff;     // ray distance − surface distance: > 0 behind the surface
    float excess;   // diff − thickness: <= 0 within the thickness
};

LinearSample linearSample(vec2 p0, vec2 p1, float k0, float k1, float w) {
    LinearSample s;
    s.p = mix(p0, p1, w);
    // The clipped end can sit exactly on the screen border; keep the read inside the image.
    s.pix = clamp(ivec2(s.p), ivec2(0), ivec2(frame.screenSize) - 1);
    s.surface = ssrSurfaceDistance(s.pix);
    s.diff = 1.0 / mix(k0, k1, w) - s.surface;
    // The write-up's thickness is linearSampleDepth·y + x: here x = pc.thickness, y = pc.thicknessScale.
    s.excess = s.diff - ssrThicknessAt(s.surface);
    return s;
}

bool ssrTrace(SsrRay ray, out vec2 hitPixel) {
    hitPixel = vec2(0.0);
    // The write-up's own frustum clip (ray.p1/k1 are clipped in screen space; not used here).
    vec3 end = linearFrustumClip(ray.viewOrigin, ray.viewEnd);
    float k0, k1;
    vec2 p0 = ssrProject(ray.viewOrigin, k0);
    vec2 p1 = ssrProject(end, k1);
    float pixels = length(p1 - p0);
    if (pixels < 1.0) return false;
    // Few steps for a short segment, at most pc.maxSteps for a long one.
    uint steps = uint(clamp(ceil(pixels / kSsrLinearPixelsPerStep), 1.0, float(max(pc.maxSteps, 1u))));

    float w1 = 0.0, w2 = 0.0;  // this step and the one before
    bool hit = false, lastBehind = false;
    bool potential = false;
    float potentialExcess = 1e30;
    vec2 potentialW = vec2(0.0);
    LinearSample hitSample = LinearSample(vec2(0.0), ivec2(0), 0.0, 0.0, 0.0);
    for (uint i = 1u; i <= steps; ++i) {
        w2 = w1;
        w1 = float(i) / float(steps);
        LinearSample s = linearSample(p0, p1, k0, k1, w1);
        if (s.diff > 0.0) {
            if (s.excess <= 0.0) {
                hit = true;
                hitSample = s;
                break;
            }
            // Dived behind deeper than the thickness right after being in front: maybe a surface
            // the step jumped across (steep ray) rather than an object passed behind. Keep the
            // shallowest, by the write-up's thicknessDiff = (diff − x) / surface distance, and march on.
            float rel = (s.diff - pc.thickness) / s.surface;
            if (!lastBehind && rel < potentialExcess) {
                potential = true;
                potentialExcess = rel;
                potentialW = vec2(w1, w2);
            }
        }
        lastBehind = s.diff > 0.0;
    }
    if (!hit && !potential) return false;
    if (!hit) {
        w1 = potentialW.x;
        w2 = potentialW.y;
    }
    // Binary search between the step before (in front) and the step that went behind: keep the
    // shallowest sample within the thickness. The write-up's shader interpolates at w1 instead of
    // the midpoint w here, so its search never moves; this one samples the midpoint.
    bool found = hit;
    LinearSample best = hitSample;
    for (uint j = 0u; j < kSsrLinearRefineSteps; ++j) {
        float w = 0.5 * (w1 + w2);
        LinearSample s = linearSample(p0, p1, k0, k1, w);
        if (s.diff > 0.0) {
            w1 = w;
            if (s.excess <= 0.0 && (!found || s.diff <= best.diff)) {
                best = s;
                found = true;
            }
        } else {
            w2 = w;
        }
    }
    if (!found) return false;
    hitPixel = vec2(best.pix) + 0.5;
    return true;
}
