#version 460
#extension GL_GOOGLE_include_directive : require
// TAA resolve: the current (jittered) HDR frame blended with last frame's resolved image, fetched where
// this pixel's surface was then. Writes the new history, which is also the frame's output.
#include "common/bindings.glsl"
#include "taa/taa.h"
#include "taa/taa_motion.glsl"

layout(local_size_x = kTaaGroupSize, local_size_y = kTaaGroupSize) in;
layout(set = 0, binding = 1) uniform sampler2D currentColor;  // nearest
layout(set = 0, binding = 2) uniform sampler2D depthTex;      // nearest
layout(set = 0, binding = 3) uniform sampler2D historyColor;  // linear, clamped
layout(set = 0, binding = 4, rgba16f) uniform writeonly image2D outColor;
layout(push_constant, scalar) uniform Push { TaaPush pc; };

float luma(vec3 c) { return dot(c, vec3(0.2126, 0.7152, 0.0722)); }
// Blending in a compressed space keeps one bright sample from dominating its neighbours (Karis'
// c / (1 + luma)); it is inverted exactly after the blend.
vec3 compress(vec3 c) { return c / (1.0 + luma(c)); }
vec3 expand(vec3 c) { return c / max(1.0 - luma(c), 1e-4); }
vec3 toYCoCg(vec3 c) { return vec3(0.25 * c.r + 0.5 * c.g + 0.25 * c.b, 0.5 * c.r - 0.5 * c.b, -0.25 * c.r + 0.5 * c.g - 0.25 * c.b); }
vec3 fromYCoCg(vec3 c) { return vec3(c.x + c.y - c.z, c.x + c.z, c.x - c.y - c.z); }

// Catmull-Rom history sample. Per axis the two middle weights share one bilinear tap placed between
// their texels (exact, both being positive); of the 3×3 taps that leaves, the four corners carry the
// product of two small outer weights and are dropped (5 taps, renormalised). At a texel centre, where
// a still camera samples, the filter is that texel: one fetch.
vec3 sampleHistoryCatmullRom(vec2 uv) {
    vec2 size = frame.screenSize;
    vec2 pos = uv * size - 0.5;
    vec2 nearest = round(pos);
    if (all(lessThan(abs(pos - nearest), vec2(1.0 / 512.0))))
        return texelFetch(historyColor, clamp(ivec2(nearest), ivec2(0), ivec2(size) - 1), 0).rgb;
    vec2 base = floor(pos);
    vec2 f = pos - base;
    vec2 w0 = f * (-0.5 + f * (1.0 - 0.5 * f));
    vec2 w1 = 1.0 + f * f * (-2.5 + 1.5 * f);
    vec2 w2 = f * (0.5 + f * (2.0 - 1.5 * f));
    vec2 w3 = f * f * (-0.5 + 0.5 * f);
    vec2 w12 = w1 + w2;
    vec2 uv0 = (base - 0.5) / size;
    vec2 uv12 = (base + 0.5 + w2 / w12) / size;
    vec2 uv3 = (base + 2.5) / size;
    vec3 sum = textureLod(historyColor, uv12, 0.0).rgb * (w12.x * w12.y);
    sum += textureLod(historyColor, vec2(uv0.x, uv12.y), 0.0).rgb * (w0.x * w12.y);
    sum += textureLod(historyColor, vec2(uv3.x, uv12.y), 0.0).rgb * (w3.x * w12.y);
    sum += textureLod(historyColor, vec2(uv12.x, uv0.y), 0.0).rgb * (w12.x * w0.y);
    sum += textureLod(historyColor, vec2(uv12.x, uv3.y), 0.0).rgb * (w12.x * w3.y);
    float weight = w12.x * w12.y + (w0.x + w3.x) * w12.y + w12.x * (w0.y + w3.y);
    // The negative lobes can ring below zero next to a bright edge.
    return max(sum / weight, vec3(0.0));
}

// Moves `history` toward the box's centre until it lies inside the box (per-axis extents).
vec3 clipToBox(vec3 history, vec3 center, vec3 extents) {
    vec3 offset = history - center;
    vec3 units = abs(offset / max(extents, vec3(1e-5)));
    float largest = max(units.x, max(units.y, units.z));
    return largest > 1.0 ? center + offset / largest : history;
}

// The group's pixels and a one-pixel border, loaded once: each pixel reads its 3×3 neighbourhood from
// here instead of nine colour and nine depth fetches. xyz: compressed YCoCg colour, w: depth.
const int kTile = int(kTaaGroupSize) + 2;
shared vec4 tile[kTile * kTile];

void main() {
    ivec2 size = ivec2(frame.screenSize);
    ivec2 origin = ivec2(gl_WorkGroupID.xy) * int(kTaaGroupSize) - 1;
    for (uint i = gl_LocalInvocationIndex; i < uint(kTile * kTile); i += kTaaGroupSize * kTaaGroupSize) {
        ivec2 q = clamp(origin + ivec2(int(i) % kTile, int(i) / kTile), ivec2(0), size - 1);
        tile[i] = vec4(toYCoCg(compress(texelFetch(currentColor, q, 0).rgb)), texelFetch(depthTex, q, 0).r);
    }
    barrier();
    ivec2 pix = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(pix, size))) return;

    // Neighbourhood statistics of the current frame, and the nearest depth around the pixel (so that
    // an edge's pixels follow the foreground's motion, not the background's).
    vec3 m1 = vec3(0.0), m2 = vec3(0.0);
    float nearestDepth = 0.0;  // reverse-Z: larger is nearer
    ivec2 local = ivec2(gl_LocalInvocationID.xy) + 1;
    for (int y = -1; y <= 1; ++y)
        for (int x = -1; x <= 1; ++x) {
            vec4 t = tile[(local.y + y) * kTile + local.x + x];
            m1 += t.xyz;
            m2 += t.xyz * t.xyz;
            nearestDepth = max(nearestDepth, t.w);
        }
    vec3 mean = m1 / 9.0;
    vec3 sigma = sqrt(max(m2 / 9.0 - mean * mean, vec3(0.0)));
    vec3 currentY = tile[local.y * kTile + local.x].xyz;

    float prevW;
    vec2 historyUv = previousUv((vec2(pix) + 0.5) * frame.invScreenSize, nearestDepth, prevW);
    bool onScreen = prevW > 0.0 && all(greaterThanEqual(historyUv, vec2(0.0))) && all(lessThanEqual(historyUv, vec2(1.0)));

    vec3 resolved = currentY;
    if (pc.historyValid != 0u && onScreen) {
        vec3 history = toYCoCg(compress(sampleHistoryCatmullRom(historyUv)));
        history = clipToBox(history, mean, kTaaClipSigma * sigma + vec3(1e-4));
        float difference = abs(currentY.x - history.x) / max(max(currentY.x, history.x), 0.2);
        float agreement = 1.0 - difference;
        float feedback = mix(kTaaFeedbackMin, kTaaFeedbackMax, agreement * agreement);
        resolved = mix(currentY, history, feedback);
    }
    vec3 outRgb = expand(fromYCoCg(resolved));
    // A non-finite history (never expected) must not live on in every later frame.
    if (any(isnan(outRgb)) || any(isinf(outRgb))) outRgb = expand(fromYCoCg(currentY));
    imageStore(outColor, pix, vec4(outRgb, 1.0));
}
