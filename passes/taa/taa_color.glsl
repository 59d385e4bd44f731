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

// True where the history is fetched at a texel centre, to rounding: nothing moved there (a still
// camera over a still surface), so the history is that texel, unfiltered.
bool atTexelCentre(vec2 uv) {
    vec2 pos = uv * frame.screenSize - 0.5;
    return all(lessThan(abs(pos - round(pos)), vec2(1.0 / 512.0)));
}

// The texel nearest to `uv`, on the screen: where a fetch at a texel centre reads.
ivec2 nearestTexel(vec2 uv) { return clamp(ivec2(round(uv * frame.screenSize - 0.5)), ivec2(0), ivec2(frame.screenSize) - 1); }

// The most of a history fetched at `uv` to keep (taa.h kTaaMotionCap): 1 at a texel centre, 1 − strength
// from about a tenth of a texel off it. With strength 0 it is exactly 1, and min(feedback, 1) is the feedback.
float motionFeedbackCap(vec2 uv, float strength) {
    vec2 f = fract(uv * frame.screenSize - 0.5);
    vec2 softening = 4.0 * f * (1.0 - f);
    return 1.0 - strength * min(1.0, 3.0 * max(softening.x, softening.y));
}

// Moves `history` toward the box's centre until it lies inside the box (per-axis extents).
vec3 clipToBox(vec3 history, vec3 center, vec3 extents) {
    vec3 offset = history - center;
    vec3 units = abs(offset / max(extents, vec3(1e-5)));
    float largest = max(units.x, max(units.y, units.z));
    return largest > 1.0 ? center + offset / largest : history;
}

// taa_average=1 (the *_average shader variants): the history's frames, counted beside it (its
// "samples" image, x: frames held, y: consecutive still frames), and its "spread" image: what the
// current frames' luma did over that still run, its lowest and highest (`range`, taa_still_range=1) or
// its mean and variance. A new history holds one frame, which may start a still run.
const vec2 kFirstSamples = vec2(1.0);
vec2 firstSpread(vec3 currentY, bool range) { return vec2(currentY.x, range ? currentY.x : 0.0); }

struct HistoryBlend {
    vec3 history;    // clipped, compressed YCoCg: the new history is mix(current, history, feedback)
    float feedback;  // the history's share
    vec2 samples;    // what the new history holds
    vec2 spread;     // its still run's luma mean and variance
};

// How to blend the current frame's YCoCg with the history fetched at `historyUv` (both compressed
// YCoCg): the history clipped to the neighbourhood's variance box (mean ± k·sigma), and its share. The
// first kTaaHeldSamples frames of a history get equal shares; a still pixel (history at a texel centre,
// inside a wider box) averages its last kTaaStillSamples frames, one whole jitter cycle, and then keeps
// them until the box no longer holds them, or, with `spreadSigma` > 0 (taa.h kTaaSpreadSigma), until the
// frame's luma leaves the spread the run has shown: its range (`range`) or kTaaSpreadSigma standard
// deviations around its mean. No share above `feedbackCap` (motionFeedbackCap, or 1).
HistoryBlend blendHistory(vec3 currentY, vec3 historyY, vec3 mean, vec3 sigma, vec2 historyUv, sampler2D samplesTex, sampler2D spreadTex,
                          bool spreadKept, float feedbackCap, float spreadSigma, bool range) {
    bool still = atTexelCentre(historyUv);
    vec3 h = clipToBox(historyY, mean, (still ? kTaaStillClipSigma : kTaaClipSigma) * sigma + vec3(1e-4));
    vec2 held = textureLod(samplesTex, historyUv, 0.0).xy;  // bilinear, as the history (a texel centre: that texel)
    // Only a still pixel's run has moments, read at its texel (the history's, to 1/512 pixel), and only
    // where they are kept (`spreadKept`: taa_still_spread=1; otherwise spreadTex is a stand-in).
    vec2 run = still && spreadKept ? texelFetch(spreadTex, nearestTexel(historyUv), 0).xy : vec2(0.0);
    // A still pixel whose frame lies within the spread its own still run has shown keeps its history
    // whole: one jittered frame's neighbourhood may sit on one side of an edge the cycle straddles. The
    // range holds from the run's first frame on: a line thinner than a pixel, which most of the cycle's
    // offsets miss, lies outside a few frames' variance but inside their range.
    bool withinRun = range ? held.y >= 1.0 && currentY.x >= run.x - kTaaSpreadFloor && currentY.x <= run.y + kTaaSpreadFloor
                           : held.y >= kTaaSpreadSamples && abs(currentY.x - run.x) <= spreadSigma * sqrt(max(run.y, 0.0)) + kTaaSpreadFloor;
    if (spreadSigma > 0.0 && still && withinRun) h = historyY;
    bool stillRun = still && h == historyY;  // nothing clipped
    float feedback = min(min(historyFeedback(currentY.x, h.x), held.x / (held.x + 1.0)), feedbackCap);
    if (stillRun) feedback = held.y >= kTaaStillSamples ? 1.0 : max(feedback, held.y / (held.y + 1.0));
    vec2 samples = vec2(min(held.x + 1.0, kTaaHeldSamples), stillRun ? min(held.y + 1.0, kTaaStillSamples) : 0.0);
    vec2 spread = firstSpread(currentY, range);
    if (stillRun) {
        // The run's range or luma moments (Welford's update), one frame more, until the run holds the
        // whole jitter cycle: then they stay what the history, kept whole from then on, averaged.
        float runMean = run.x + (currentY.x - run.x) / samples.y;
        vec2 grown = range ? vec2(min(run.x, currentY.x), max(run.y, currentY.x))
                           : vec2(runMean, run.y + ((currentY.x - run.x) * (currentY.x - runMean) - run.y) / samples.y);
        spread = held.y >= kTaaStillSamples ? run : grown;
    }
    return HistoryBlend(h, feedback, samples, spread);
}

// Catmull-Rom history sample. Per axis the two middle weights share one bilinear tap placed between
// their texels (exact, both being positive); of the 3×3 taps that leaves, the four corners carry the
// product of two small outer weights and are dropped (5 taps, renormalised). At a texel centre, where
// a still camera samples, the filter is that texel: one fetch.
vec3 sampleCatmullRom(sampler2D history, vec2 uv) {
    vec2 size = frame.screenSize;
    vec2 pos = uv * size - 0.5;
    if (atTexelCentre(uv)) return texelFetch(history, nearestTexel(uv), 0).rgb;
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

