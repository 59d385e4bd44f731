// The reflection's own history (--set taa=1): the technique's reflection image blended with last
// frame's accumulated reflection, fetched by --set reproject (taa.h kReproject*), before the composite.
// Compiled as taa_reflection.comp and taa_reflection_average.comp (PPR_TAA_AVERAGE, taa_average=1: the
// history counts its frames, taa_color.glsl).
// The history's alpha holds the view depth of each pixel's virtual point (the reflected point mirrored
// through the reflector, on the pixel's view ray at the reflected path's length), so that `virtual`
// can tell a disoccluded history from its own, as a depth-history reprojection would.
// A reflected point on a moving draw (its motion slot in the path image's tag) is carried back to
// where that draw was last frame before it is mirrored, so a moving object's reflection follows it.
#include "common/bindings.glsl"
#include "common/reflection.h"
#include "gpu/scene_data.h"
#include "taa/taa.h"
#include "taa/taa_color.glsl"
#include "taa/taa_motion.glsl"

#include "taa/taa_tile.glsl"

layout(set = 0, binding = 1) uniform sampler2D reflectionTex;  // common/reflection.h, nearest
layout(set = 0, binding = 2) uniform sampler2D depthTex;
layout(set = 0, binding = 3) uniform sampler2D normalTex;
layout(set = 0, binding = 4) uniform sampler2D distanceTex;    // reflected-path image (common/reflection.h)
layout(set = 0, binding = 5) uniform sampler2D historyTex;     // linear, clamped
layout(set = 0, binding = 6, rgba16f) uniform writeonly image2D outShown;
layout(set = 0, binding = 7, rgba16f) uniform writeonly image2D outHistory;
layout(set = 0, binding = 8, scalar) readonly buffer Motions { MotionData motions[]; };
#ifdef PPR_TAA_AVERAGE
layout(set = 0, binding = 9) uniform sampler2D historySamples;  // what the history holds (taa_color.glsl), linear
layout(set = 0, binding = 10, rg16f) uniform writeonly image2D outSamples;
layout(set = 0, binding = 11) uniform sampler2D historySpread;  // a still run's luma moments (taa_color.glsl), nearest
layout(set = 0, binding = 12, rg16f) uniform writeonly image2D outSpread;
#endif
#include "taa/reflection_motion.glsl"
layout(push_constant, scalar) uniform Push { TaaReflectionPush pc; };

// A history texel with alpha below this had no reflection, or one of unknown depth.
const float kKnownDepth = 1e-2;

#ifdef PPR_TAA_AVERAGE
// The reflection's history at `uv` blended bilinearly from those of its four texels that held one (alpha
// above 0); alpha 0 where none did. A rim's texels border others without a reflection, whose zeros a
// plain bilinear fetch would blend in.
vec4 keptHistory(vec2 uv) {
    vec2 pos = uv * frame.screenSize - 0.5;
    ivec2 base = ivec2(floor(pos));
    vec2 f = pos - floor(pos);
    vec4 sum = vec4(0.0);
    float weight = 0.0;
    for (int i = 0; i < 4; ++i) {
        ivec2 o = ivec2(i & 1, i >> 1);
        ivec2 texel = clamp(base + o, ivec2(0), ivec2(frame.screenSize) - 1);
        vec4 h = texelFetch(historyTex, texel, 0);
        if (h.a <= 0.0) continue;
        vec2 w2 = mix(1.0 - f, f, vec2(o));
        float w = w2.x * w2.y;
        sum += w * h;
        weight += w;
    }
    return weight > 0.0 ? sum / weight : vec4(0.0);
}
#endif

// Resolves one pixel (main: the invocation's column of its tile).
void resolvePixel(ivec2 pix) {
    ivec2 size = ivec2(frame.screenSize);
    if (any(greaterThanEqual(pix, size))) return;
    vec4 current = texelFetch(reflectionTex, pix, 0);
    if (current.a == kReflectionNone) {
        // pc.clearedNone: the cleared images already hold the zeros this pixel would store (most of the
        // screen; those stores were 40 % of the pass on lavapipe, docs/temporal.md "Cost").
        if (pc.clearedNone == 0u || current != vec4(0.0)) imageStore(outShown, pix, current);
#ifdef PPR_TAA_AVERAGE
        // A pixel that the jitter takes off a reflector's rim keeps its reflection's history (and, still,
        // its still run) for the frames that bring the reflection back. Still, that is its own texel; in
        // motion (taa_rim_keep), the history where its surface was, blended from the texels there that
        // held a reflection: otherwise a rim pixel's reflection (often a thin band of what stands on the
        // reflector's edge) starts again from one jittered frame, or from a neighbour's, every time.
        // The counts are read first, being half the history's size: a history that holds frames (x > 0)
        // holds a reflection. Its still run's moments are kept with it.
        vec4 kept = vec4(0.0);
        vec2 keptSamples = texelFetch(historySamples, pix, 0).xy;
        if (pc.historyValid != 0u && keptSamples.x > 0.0) {
            float prevW;
            vec2 historyUv = previousUv((vec2(pix) + 0.5) * frame.invScreenSize, texelFetch(depthTex, pix, 0).r, prevW);
            if (prevW > 0.0 && atTexelCentre(historyUv)) {
                kept = texelFetch(historyTex, pix, 0);
            } else if (pc.rimKeep != 0u && prevW > 0.0 && all(greaterThanEqual(historyUv, vec2(0.0))) && all(lessThanEqual(historyUv, vec2(1.0)))) {
                // A stand-in, counted as one frame (a texel with a reflection holds at least one): the frame
                // that brings the reflection back gets an equal share (holding the texels' frames, the
                // mirror's strafe scored 0.11 dB lower). Moving: no still run.
                kept = keptHistory(historyUv);
                keptSamples = vec2(1.0, 0.0);
            }
        }
        if (kept.a <= 0.0) keptSamples = vec2(0.0);
        if (pc.clearedNone != 0u && kept == vec4(0.0)) return;
        imageStore(outHistory, pix, kept);
        imageStore(outSamples, pix, vec4(keptSamples, 0.0, 0.0));
        if (pc.stillSpread > 0.0) imageStore(outSpread, pix, keptSamples.x > 0.0 ? texelFetch(historySpread, pix, 0) : vec4(0.0));
#else
        if (pc.clearedNone == 0u) imageStore(outHistory, pix, vec4(0.0));
#endif
        return;
    }
    // Neighbourhood of the reflection alone (pixels with one), compressed YCoCg; for `virtual`, also the
    // range of its reflected path lengths.
    vec3 m1 = vec3(0.0), m2 = vec3(0.0);
    float count = 0.0;
    bool pathRange = pc.hasDistance != 0u && pc.mode == kReprojectVirtual;
    float shortestPath = 1e30, longestPath = 0.0;
    bool movingNearby = false;  // a draw that moved is reflected here or beside: its trail is disocclusion
    for (int y = -1; y <= 1; ++y)
        for (int x = -1; x <= 1; ++x) {
            ivec2 q = clamp(pix + ivec2(x, y), ivec2(0), size - 1);
            vec4 t = texelFetch(reflectionTex, q, 0);
            if (t.a == kReflectionNone) continue;
            vec3 c = toYCoCg(compress(t.rgb));
            m1 += c;
            m2 += c * c;
            count += 1.0;
            if (pathRange) {
                vec2 p = texelFetch(distanceTex, q, 0).xy;
                uint s = pathMotionSlot(p.y);  // a slot at rest this frame holds exactly the identity
                movingNearby = movingNearby || (s != 0u && motions[s].toPrevious != mat4(1.0));
                if (p.x > 0.0) {
                    shortestPath = min(shortestPath, p.x);
                    longestPath = max(longestPath, p.x);
                }
            }
        }
    vec3 mean = m1 / count;
    vec3 sigma = sqrt(max(m2 / count - mean * mean, vec3(0.0)));
    vec3 currentY = toYCoCg(compress(current.rgb));

    vec2 uv = (vec2(pix) + 0.5) * frame.invScreenSize;
    float depth = texelFetch(depthTex, pix, 0).r;
    float prevW;
    vec2 historyUv = previousUv(uv, depth, prevW);
    // The still spread only where the surface is still too: `candidates` fetches a far reflection at a
    // texel centre (its parallax-scaled vector is zero) while the camera moves and the reflection with it.
    float stillSpread = atTexelCentre(historyUv) ? pc.stillSpread : 0.0;
    vec2 path = pc.hasDistance != 0u ? texelFetch(distanceTex, pix, 0).xy : vec2(0.0);
    float dist = path.x;
    uint slot = pathMotionSlot(path.y);
    vec3 surface = worldFromDepth(uv, depth);
    vec3 view = normalize(surface - frame.cameraPos.xyz);
    vec4 virtualPoint = vec4(frame.cameraPos.xyz + view * dist, 1.0);
    vec3 n = normalize(texelFetch(normalTex, pix, 0).xyz);
    float expectedW = 0.0;  // virtual: the view depth last frame's history should hold there
    if (dist > 0.0 && pc.mode == kReprojectVirtual) {
        historyUv = previousUvOfReflection(uv, surface, view, n, dist, slot, prevW);
        expectedW = prevW;
    } else if (dist > 0.0 && pc.mode == kReprojectCandidates) {
        // The seed note's candidates: the motion at the incidence (the surface) and at the intersection
        // (the reflected point, where it is seen on screen, moved with its draw), each also
        // parallax-scaled; the smallest wins.
        vec3 reflected = reflectedPoint(surface, view, n, dist);
        vec3 reflectedBefore = pointBefore(reflected, slot);
        vec4 clip = frame.viewProj * vec4(reflected, 1.0);
        vec2 reflectedUv = clip.xy / clip.w * 0.5 + 0.5;
        float reflectedW;
        vec2 atIntersection = previousUvOfPoint(reflectedUv, vec4(reflectedBefore, 1.0), reflectedW) - reflectedUv;
        vec2 atIncidence = historyUv - uv;
        float parallax = clamp(1.0 - dist * kTaaParallaxPerMetre, 0.0, 1.0);
        vec2 best = atIncidence;
        vec2 others[3] = vec2[3](atIntersection, atIncidence * parallax, atIntersection * parallax);
        for (int i = 0; i < 3; ++i)
            if (dot(others[i], others[i]) < dot(best, best)) best = others[i];
        historyUv = uv + best;
    }
    bool onScreen = prevW > 0.0 && all(greaterThanEqual(historyUv, vec2(0.0))) && all(lessThanEqual(historyUv, vec2(1.0)));

    vec3 resolved = currentY;
#ifdef PPR_TAA_AVERAGE
    vec2 samples = kFirstSamples;  // what the new history holds (taa_color.glsl)
    vec2 spread = firstSpread(currentY, pc.stillRange != 0u);
#endif
    if (pc.historyValid != 0u && onScreen) {
        // Colour through the bicubic filter (a bilinear one blurs a little more every frame); the stored
        // depth through the bilinear one (no overshoot).
        vec4 history = vec4(sampleCatmullRom(historyTex, historyUv), textureLod(historyTex, historyUv, 0.0).a);
        bool hadReflection = history.a > 0.0;
        // Another surface's history only if its depth lies outside what the neighbourhood reflects (each
        // neighbour's path scaled to this pixel's ray): on a still reflected silhouette the jitter moves
        // the pixel's own path from one side to the other every frame, and both sides are its history.
        // Beside a moving draw's reflection the pixel's own depth decides, as a disocclusion is likely.
        float perPath = dist > 0.0 ? expectedW / dist : 0.0;
        float rangeNearest = min(expectedW, shortestPath * perPath) * (1.0 - kTaaVirtualDepthTolerance);
        float rangeFarthest = max(expectedW, longestPath * perPath) * (1.0 + kTaaVirtualDepthTolerance);
        bool withinRange = history.a >= rangeNearest && history.a <= rangeFarthest;
        bool ownDepth = history.a >= expectedW * (1.0 - kTaaVirtualDepthTolerance) && history.a <= expectedW * (1.0 + kTaaVirtualDepthTolerance);
        bool disoccluded = expectedW > 0.0 && history.a > kKnownDepth && !(movingNearby ? ownDepth : withinRange);
#ifdef PPR_TAA_AVERAGE
        // A still run (the history at a texel centre: nothing moved there): only the jitter changed what
        // this pixel reflects, as on a reflector's rim, where one phase of the cycle sees past an edge
        // that the others do not. Every phase is its history; the colour tests judge it. Not beside a
        // moving draw's reflection: there the depth is what tells its trail (taa_still_keep=1; the
        // counts are read only where the depth rejected the history).
        if (disoccluded && pc.stillKeep != 0u && !movingNearby && atTexelCentre(historyUv) && texelFetch(historySamples, nearestTexel(historyUv), 0).y >= 1.0)
            disoccluded = false;
#endif
        if (hadReflection && !disoccluded) {
#ifdef PPR_TAA_AVERAGE
            HistoryBlend blend = blendHistory(currentY, toYCoCg(compress(history.rgb)), mean, sigma, historyUv, historySamples, historySpread,
                                              pc.stillSpread > 0.0, motionFeedbackCap(historyUv, pc.motionCap), stillSpread, pc.stillRange != 0u);
            vec3 h = blend.history;
            float feedback = blend.feedback;
            samples = blend.samples;
            spread = blend.spread;
#else
            vec3 h = clipToBox(toYCoCg(compress(history.rgb)), mean, kTaaClipSigma * sigma + vec3(1e-4));
            float feedback = historyFeedback(currentY.x, h.x);
#endif
            resolved = mix(currentY, h, feedback);
        } else if (hadReflection && movingNearby && withinRange && pc.movingEdge != 0u && length((historyUv - uv) * frame.screenSize) < kTaaMovingEdgeMotion) {
            // taa_moving_edge=1: beside a slowly moving draw's reflection a history its depth rejects, yet
            // one the neighbours' reflected depths span, is most likely the other side of an edge the
            // jitter straddles, not a trail. Its colour is not trusted (the draw moved), but one jittered
            // sample would flip across the edge every frame: the neighbourhood's mean stands in.
            resolved = mean;
        }
    }
    vec3 rgb = expand(fromYCoCg(resolved));
    if (any(isnan(rgb)) || any(isinf(rgb))) rgb = current.rgb;
#ifdef PPR_TAA_AVERAGE
    imageStore(outSamples, pix, vec4(samples, 0.0, 0.0));
    if (pc.stillSpread > 0.0) imageStore(outSpread, pix, vec4(spread, 0.0, 0.0));
#endif
    imageStore(outShown, pix, vec4(rgb, current.a));  // the class code stays the technique's
    float currentW = (frame.viewProj * virtualPoint).w;
    imageStore(outHistory, pix, vec4(rgb, dist > 0.0 ? max(currentW, 2.0 * kKnownDepth) : kKnownDepth * 0.5));
}

void main() {
    for (uint row = 0u; row < kTaaRowsPerInvocation; ++row) resolvePixel(tileOrigin() + pixelInTile(row));
}
