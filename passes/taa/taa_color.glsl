// TAA colour space and history filter, shared by the frame resolve and the reflection history (needs
// common/bindings.glsl).
float luma(vec3 c) { return dot(c, vec3(0.2126, 0.7152, 0.0722)); }
// Blending in a compressed space keeps one bright sample from dominating its neighbours (Karis'
// c / (1 + luma)); it is inverted exactly after the blend.
vec3 compress(vec3 c) { return c / (1.0 + luma(c)); }
vec3 expand(vec3 c) { return c / max(1.0 - luma(c), 1e-4); }
vec3 toYCoCg(vec3 c) { return vec3(0.25 * c.r + 0.5 * c.g + 0.25 * c.b, 0.5 * c.r - 0.5 * c.b, -0.25 * c.r + 0.5 * c.g - 0.25 * c.b); }
vec3 fromYCoCg(vec3 c) { return vec3(c.x + c.y - c.z, c.x + c.z, c.x - c.y - c.z); }

// How much of the (clipped) history to keep: less when its luma disagrees with the current frame's, a
// change the history has not seen yet (luma as compressed YCoCg's Y).
float historyFeedback(float currentY, float historyY) {
    float agreement = 1.0 - abs(currentY - historyY) / max(max(currentY, historyY), 0.2);
    return mix(kTaaFeedbackMin, kTaaFeedbackMax, agreement * agreement);
}

// Moves `history` toward the box's centre until it lies inside the box (per-axis extents).
vec3 clipToBox(vec3 history, vec3 center, vec3 extents) {
    vec3 offset = history - center;
    vec3 units = abs(offset / max(extents, vec3(1e-5)));
    float largest = max(units.x, max(units.y, units.z));
    return largest > 1.0 ? center + offset / largest : history;
}


// Catmull-Rom history sample. Per axis the two middle weights share one bilinear tap placed between
// their texels (exact, both being positive); of the 3×3 taps that leaves, the four corners carry the
// product of two small outer weights and are dropped (5 taps, renormalised). At a texel centre, where
// a still camera samples, the filter is that texel: one fetch.
vec3 sampleCatmullRom(sampler2D history, vec2 uv) {
    vec2 size = frame.screenSize;
    vec2 pos = uv * size - 0.5;
    vec2 nearest = round(pos);
    if (all(lessThan(abs(pos - nearest), vec2(1.0 / 512.0))))
        return texelFetch(history, clamp(ivec2(nearest), ivec2(0), ivec2(size) - 1), 0).rgb;
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
    vec3 sum = textureLod(history, uv12, 0.0).rgb * (w12.x * w12.y);
    sum += textureLod(history, vec2(uv0.x, uv12.y), 0.0).rgb * (w0.x * w12.y);
    sum += textureLod(history, vec2(uv3.x, uv12.y), 0.0).rgb * (w3.x * w12.y);
    sum += textureLod(history, vec2(uv12.x, uv0.y), 0.0).rgb * (w12.x * w0.y);
    sum += textureLod(history, vec2(uv12.x, uv3.y), 0.0).rgb * (w12.x * w3.y);
    float weight = w12.x * w12.y + (w0.x + w3.x) * w12.y + w12.x * (w0.y + w3.y);
    // The negative lobes can ring below zero next to a bright edge.
    return max(sum / weight, vec3(0.0));
}

