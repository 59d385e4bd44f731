// TAA resolve body, compiled four times: taa.comp, taa_split.comp (PPR_TAA_SPLIT) and their
// *_average variants (PPR_TAA_AVERAGE, taa_average=1: the history counts its frames, taa_color.glsl).
// The current (jittered) HDR frame blended with last frame's resolved image, fetched where this
// pixel's surface was then. A reflector pixel's colour is partly its reflection, which moved with its
// virtual point, not with the surface, and which taa.reflection has already resolved along that motion:
// - whole colour (taa.comp): with `reflectionMotion` a reflector pixel's history is the mix, by the
//   composite's reflection weight (the current colour's alpha), of the fetch at the surface's motion
//   and the fetch at the reflection's. The new history is also the frame's output.
// - split (taa_split.comp): the history holds the surface part alone (the colour less weight ×
//   shown reflection) and, in alpha, the resolved weight; the output adds the resolved weight times
//   this frame's shown reflection. Nothing of the reflection is reprojected by the surface's motion, and
//   the weight's own history keeps the reflector's edge anti-aliased.
#include "common/bindings.glsl"
#include "common/reflection.h"
#include "gpu/scene_data.h"
#include "taa/taa.h"
#include "taa/taa_color.glsl"

#include "taa/taa_tile.glsl"

layout(set = 0, binding = 1) uniform sampler2D currentColor;  // nearest
layout(set = 0, binding = 2) uniform sampler2D depthTex;      // nearest
layout(set = 0, binding = 3) uniform sampler2D historyColor;  // linear, clamped
layout(set = 0, binding = 4, rgba16f) uniform writeonly image2D outColor;
layout(set = 0, binding = 5) uniform sampler2D materialTex;  // G-buffer: alpha = motion slot
layout(set = 0, binding = 6, scalar) readonly buffer Motions { MotionData motions[]; };
layout(set = 0, binding = 7) uniform sampler2D pathTex;  // the technique's reflected-path image (reflectionMotion)
#ifdef PPR_TAA_SPLIT
layout(set = 0, binding = 8) uniform sampler2D shownReflection;  // common/reflection.h (taa.reflection's output)
layout(set = 0, binding = 9, rgba16f) uniform writeonly image2D outFrame;  // the frame's output (the history is outColor)
const int kSamplesBinding = 10;
#else
const int kSamplesBinding = 8;
#endif
#ifdef PPR_TAA_AVERAGE
layout(set = 0, binding = kSamplesBinding) uniform sampler2D historySamples;  // what the history holds (taa_color.glsl), linear
layout(set = 0, binding = kSamplesBinding + 1, rg16f) uniform writeonly image2D outSamples;
#ifdef PPR_TAA_SPLIT
layout(set = 0, binding = kSamplesBinding + 2) uniform sampler2D reflectionHistory;  // taa.reflection's new history (pc.keptReflection)
const int kSpreadBinding = kSamplesBinding + 3;
#else
const int kSpreadBinding = kSamplesBinding + 2;
#endif
layout(set = 0, binding = kSpreadBinding) uniform sampler2D historySpread;  // a still run's luma moments (taa_color.glsl), nearest
layout(set = 0, binding = kSpreadBinding + 1, rg16f) uniform writeonly image2D outSpread;
#endif
#include "taa/taa_motion.glsl"
#include "taa/object_motion.glsl"
#include "taa/reflection_motion.glsl"
layout(push_constant, scalar) uniform Push { TaaPush pc; };

// The tile's pixels and a one-pixel border, loaded once: each pixel reads its 3×3 neighbourhood from
// here instead of nine colour and nine depth fetches. xyz: compressed YCoCg colour, w: depth; and the
// colour's alpha, the composite's reflection weight (split: xyz is the surface part).
const int kTile = int(kTaaTileSize) + 2;
shared vec4 tile[kTile * kTile];
shared float tileReflectionWeight[kTile * kTile];
#ifdef PPR_TAA_SPLIT
shared vec3 tileReflection[kTile * kTile];  // the shown reflection where there is one, else 0
#endif

// One pixel's 3×3 neighbourhood of the tile, [(y + 1) * 3 + x + 1], held by the invocation: walking down
// its column it reads one new row of three a pixel instead of all nine (on lavapipe each shared-memory
// read of a varying index is a per-lane loop, and the nine reads were 30 % of the pass).
struct Window {
    vec4 t[9];   // tile[]
    float w[9];  // tileReflectionWeight[]
};

// Reads the window's row y (−1, 0 or 1) around `local` from the tile.
void readWindowRow(inout Window win, ivec2 local, int y) {
    for (int x = -1; x <= 1; ++x) {
        int at = (local.y + y) * kTile + local.x + x;
        win.t[(y + 1) * 3 + x + 1] = tile[at];
        win.w[(y + 1) * 3 + x + 1] = tileReflectionWeight[at];
    }
}

// The window one pixel further down the column: rows 0 and 1 move up, row 1 is read.
void slideWindowDown(inout Window win, ivec2 local) {
    for (int i = 0; i < 6; ++i) {
        win.t[i] = win.t[i + 3];
        win.w[i] = win.w[i + 3];
    }
    readWindowRow(win, local, 1);
}

// taa_moving_filter: the current frame at the pixel's centre, from the 3×3's jittered samples (each lies
// `jitter` away from its own pixel's centre, the projection having been shifted by it): one sample
// a frame flips across a moving edge as the jitter cycles, and the history, which cannot keep a whole
// cycle there as a still pixel does, takes a share of every flip.
vec3 currentAtCentre(Window win) {
    vec2 jitter = frame.jitter.xy * 0.5 * frame.screenSize;  // NDC to pixels
    vec3 sum = vec3(0.0);
    float weights = 0.0;
    for (int y = -1; y <= 1; ++y)
        for (int x = -1; x <= 1; ++x) {
            vec2 d = vec2(x, y) - jitter;
            float w = exp(-kTaaMovingFilterSharpness * dot(d, d));
            sum += w * win.t[(y + 1) * 3 + x + 1].xyz;
            weights += w;
        }
    return sum / weights;
}

// Resolves one pixel; `local` is where it is in the shared tile (its tile position + 1, for the border),
// `win` its neighbourhood there.
void resolvePixel(ivec2 pix, ivec2 local, Window win) {
    ivec2 size = ivec2(frame.screenSize);
    if (any(greaterThanEqual(pix, size))) return;

    // Neighbourhood statistics of the current frame, and the nearest depth around the pixel (so that
    // an edge's pixels follow the foreground's motion, not the background's).
    vec3 m1 = vec3(0.0), m2 = vec3(0.0);
#ifdef PPR_TAA_SPLIT
    float weightMin = 1.0, weightMax = 0.0, brightestWeight = 0.0;
    int brightest = -1;  // the most reflective neighbour's place in the tile
#endif
    float nearestDepth = 0.0;  // reverse-Z: larger is nearer
    ivec2 nearest = ivec2(0);  // where it is (its object's motion is the one taken)
    for (int y = -1; y <= 1; ++y)
        for (int x = -1; x <= 1; ++x) {
            vec4 t = win.t[(y + 1) * 3 + x + 1];
            m1 += t.xyz;
            m2 += t.xyz * t.xyz;
#ifdef PPR_TAA_SPLIT
            float w = win.w[(y + 1) * 3 + x + 1];
            weightMin = min(weightMin, w);
            weightMax = max(weightMax, w);
            if (w > brightestWeight) {
                brightestWeight = w;
                brightest = (local.y + y) * kTile + local.x + x;
            }
#endif
            if (t.w > nearestDepth) nearest = ivec2(x, y);
            nearestDepth = max(nearestDepth, t.w);
        }
    vec3 mean = m1 / 9.0;
    vec3 sigma = sqrt(max(m2 / 9.0 - mean * mean, vec3(0.0)));
    vec3 currentY = win.t[4].xyz;

    float prevW;
    uint slot = motionSlotAt(clamp(pix + nearest, ivec2(0), size - 1));
    vec2 historyUv = previousUvMoving((vec2(pix) + 0.5) * frame.invScreenSize, nearestDepth, slot, prevW);
#ifndef PPR_TAA_SPLIT
    float reflectionWeight = 0.0;  // 0: the surface's fetch alone
    vec2 reflectionUv = vec2(0.0);
    if (pc.reflectionMotion != 0u) {
        float w = win.w[4];
        vec2 path = w > 0.0 ? texelFetch(pathTex, pix, 0).xy : vec2(0.0);
        // Only a still reflected point: for a moving one, the mix measured worse than the surface's
        // fetch alone (docs/temporal.md), and the reflection's own history already follows it.
        if (path.x > 0.0 && pathMotionSlot(path.y) == 0u) {
            vec2 uv = (vec2(pix) + 0.5) * frame.invScreenSize;
            vec3 surface = worldFromDepth(uv, texelFetch(depthTex, pix, 0).r);
            vec3 view = normalize(surface - frame.cameraPos.xyz);
            float reflectionW;  // a still reflected point: the tangent plane (normal) plays no part
            reflectionUv = previousUvOfReflection(uv, surface, view, vec3(0.0), path.x, 0u, reflectionW);
            if (reflectionW > 0.0 && all(greaterThanEqual(reflectionUv, vec2(0.0))) && all(lessThanEqual(reflectionUv, vec2(1.0))))
                reflectionWeight = w;
        }
    }
#endif
    bool onScreen = prevW > 0.0 && all(greaterThanEqual(historyUv, vec2(0.0))) && all(lessThanEqual(historyUv, vec2(1.0)));

    vec3 resolved = currentY;
#ifdef PPR_TAA_SPLIT
    float currentWeight = win.w[4];
    float resolvedWeight = currentWeight;
    // A pixel with a reflection adds its own; one beside a reflector (whose history may hold some of
    // its weight) its most reflective neighbour's. One read of the tile.
    int reflectionAt = currentWeight > 0.0 ? local.y * kTile + local.x : brightest;
    vec3 reflection = reflectionAt >= 0 ? tileReflection[reflectionAt] : vec3(0.0);
#endif
#ifdef PPR_TAA_AVERAGE
    vec2 samples = kFirstSamples;  // what the new history holds (taa_color.glsl)
    vec2 spread = firstSpread(currentY, pc.stillRange != 0u);
#endif
    if (pc.historyValid != 0u && onScreen) {
        // A moving draw's pixel (or one beside it, whose nearest neighbour moves) blends the current
        // frame filtered to its centre, while the draw moves (its motion is exactly the identity when
        // it stands still: scene_motion.cpp); the rest keep their jittered sample, whose whole cycle a
        // still pixel's run averages.
        bool objectMoves = slot != 0u && motions[slot].toPrevious != mat4(1.0);
        vec3 current = pc.movingFilter != 0u && objectMoves ? currentAtCentre(win) : currentY;
        vec3 historyRgb = sampleCatmullRom(historyColor, historyUv);
#ifndef PPR_TAA_SPLIT
        // Where both fetches coincide to rounding (1/1000 pixel: a still view) the mix is the surface's
        // fetch. Not more: a slow camera's sub-pixel differences add up over the frames.
        vec2 apart = (reflectionUv - historyUv) * frame.screenSize;
        if (reflectionWeight > 0.0 && dot(apart, apart) > 1e-6)
            historyRgb = mix(historyRgb, sampleCatmullRom(historyColor, reflectionUv), reflectionWeight);
#endif
        vec3 history = toYCoCg(compress(historyRgb));
#ifdef PPR_TAA_AVERAGE
        HistoryBlend blend = blendHistory(current, history, mean, sigma, historyUv, historySamples, historySpread, pc.stillSpread > 0.0,
                                          motionFeedbackCap(historyUv, pc.motionCap), pc.stillSpread, pc.stillRange != 0u);
        history = blend.history;
        float feedback = blend.feedback;
        samples = blend.samples;
        spread = blend.spread;
#else
        history = clipToBox(history, mean, kTaaClipSigma * sigma + vec3(1e-4));
        float feedback = historyFeedback(current.x, history.x);
#endif
        resolved = mix(current, history, feedback);
#ifdef PPR_TAA_SPLIT
        // The weight is the surface's (Fresnel × reflectance): it follows the surface, clamped to its
        // neighbourhood as the colour is clipped.
        float historyWeight = textureLod(historyColor, historyUv, 0.0).a;
#ifdef PPR_TAA_AVERAGE
        // Not in a still run: there the weights the jitter gives the rim are what the history averages.
        if (samples.y == 0.0)
#endif
            historyWeight = clamp(historyWeight, weightMin, weightMax);
        resolvedWeight = mix(currentWeight, historyWeight, feedback);
#endif
    }
#ifdef PPR_TAA_AVERAGE
    imageStore(outSamples, pix, vec4(samples, 0.0, 0.0));
    if (pc.stillSpread > 0.0) imageStore(outSpread, pix, vec4(spread, 0.0, 0.0));
#endif
    vec3 outRgb = expand(fromYCoCg(resolved));
    // A non-finite history (never expected) must not live on in every later frame.
    if (any(isnan(outRgb)) || any(isinf(outRgb))) outRgb = expand(fromYCoCg(currentY));
#ifdef PPR_TAA_SPLIT
    if (isnan(resolvedWeight)) resolvedWeight = currentWeight;
#ifdef PPR_TAA_AVERAGE
    // One the jitter took off a reflector's rim this frame, whose history holds some weight: the
    // reflection its reflection history kept (alpha: a depth, so one is there), which does not change
    // with the jitter as the neighbours' do. Read only there: elsewhere it would be multiplied by 0.
    if (currentWeight == 0.0 && resolvedWeight > 0.0 && pc.keptReflection != 0u) {
        vec4 kept = texelFetch(reflectionHistory, pix, 0);
        if (kept.a > 0.0) reflection = kept.rgb;
    }
#endif
    imageStore(outColor, pix, vec4(outRgb, resolvedWeight));
    imageStore(outFrame, pix, vec4(outRgb + resolvedWeight * reflection, 1.0));
#else
    imageStore(outColor, pix, vec4(outRgb, 1.0));
#endif
}

void main() {
    ivec2 size = ivec2(frame.screenSize);
    ivec2 origin = tileOrigin() - 1;
    for (uint i = gl_LocalInvocationIndex; i < uint(kTile * kTile); i += kThreads) {
        ivec2 q = clamp(origin + ivec2(int(i) % kTile, int(i) / kTile), ivec2(0), size - 1);
        vec4 c = texelFetch(currentColor, q, 0);
#ifdef PPR_TAA_SPLIT
        // The composite's weight is non-zero exactly where it blended a reflection.
        vec3 r = c.a > 0.0 ? texelFetch(shownReflection, q, 0).rgb : vec3(0.0);
        tileReflection[i] = r;
        c.rgb -= c.a * r;  // the composite's mix, less its reflection term (exact for grey Fresnel)
#endif
        tile[i] = vec4(toYCoCg(compress(c.rgb)), texelFetch(depthTex, q, 0).r);
        tileReflectionWeight[i] = c.a;
    }
    barrier();
    Window win;
    for (uint row = 0u; row < kTaaRowsPerInvocation; ++row) {
        ivec2 p = pixelInTile(row);
        if (row == 0u) {
            for (int y = -1; y <= 1; ++y) readWindowRow(win, p + 1, y);
        } else {
            slideWindowDown(win, p + 1);
        }
        resolvePixel(tileOrigin() + p, p + 1, win);
    }
}
