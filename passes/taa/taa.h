// Temporal anti-aliasing (host/device shared): the resolve's constants and push block.
#ifndef PPR_TAA_H
#define PPR_TAA_H
#include "shader/shared.h"

// Both resolves work in 16×16-pixel tiles, one workgroup each (taa_body.glsl loads a tile and its border
// into shared memory). An invocation resolves a column of 256 / threads pixels, one above the other:
// --set taa_threads (specialization constant 0). On a CPU device 16 (a whole column each), because
// lavapipe runs a workgroup's invocations as 8-wide SIMD batches and switches between all of them at a
// barrier, and even without one pays per batch: 16 invocations made `taa` 27 % and `taa.reflection`
// 35 % cheaper than 256 at 1280x720 (docs/temporal.md, Cost); on a GPU 256, one pixel each.
PPR_CONST(uint, kTaaTileSize, 16u)
PPR_CONST(uint, kTaaThreads, 16u)
PPR_CONST(uint, kTaaThreadsGpu, 256u)
// Weight of the history: between these, by how much the current and the clipped history's luma agree
// (a large difference is a change the history has not seen yet, so it keeps less of it).
PPR_CONST(float, kTaaFeedbackMin, 0.88f)
PPR_CONST(float, kTaaFeedbackMax, 0.97f)
// taa_average=1: each history pixel counts its frames (a "samples" image beside it). The first
// kTaaHeldSamples frames after a cut or a disocclusion get equal shares (above that the feedback above
// keeps more); a still pixel (its history fetched at a texel centre and inside the still clipping box)
// averages kTaaStillSamples frames, one whole jitter cycle, with equal shares, and then keeps that
// average until the box no longer holds it: a still view converges and stops flickering.
PPR_CONST(float, kTaaHeldSamples, 32.0f)
PPR_CONST(float, kTaaStillSamples, 16.0f)
// taa_motion_cap=1 (with taa_average=1): the frame's history keeps at most 1 − this of itself wherever it
// was fetched between texels, ramping back to 1 within a tenth of a texel of a centre (f being the
// fetch's offset on the larger axis: 1 − this × min(1, 3 × 4f(1 − f))). Each fetch between texels
// softens the history a little (Catmull-Rom only partly restores its detail), and at a feedback near
// 0.97 the softening of a dozen frames adds up, small offsets included; a still pixel (f = 0) and
// whole-pixel motion keep the feedback. (The proportional cap, 1 − this × 4f(1 − f), scored the same
// under a strafe and 0.2–0.4 dB lower under an orbit, docs/temporal.md.)
// taa_reflection_cap=1 applies it to the reflection's own history too (taa.reflection; off by default: it
// lifts the surface's-motion reprojection more than the virtual point's, docs/temporal.md).
PPR_CONST(float, kTaaMotionCap, 0.3f)
// taa_still_spread=1 (with taa_average=1): a still pixel whose run holds at least kTaaSpreadSamples
// frames keeps its history unclipped while the frame's luma lies within kTaaSpreadSigma standard
// deviations (plus the floor, about one 8-bit level) of the run's own luma mean. One jittered frame's
// 3×3 may lie wholly on one side of an edge that the jitter cycle straddles; the pixel's own frames
// show how far it moves.
// taa_still_range=1 (with taa_still_spread=1): the test is the run's luma range instead, from its first
// frame on (plus the same floor): a line thinner than a pixel lies outside a few frames' variance but
// inside their range. taa_still_keep=1: a still pixel's reflection history is not rejected as another
// surface's when only the jitter changed the reflected path (a reflector's rim), unless a moving draw is
// reflected there or beside.
PPR_CONST(float, kTaaSpreadSamples, 4.0f)
PPR_CONST(float, kTaaSpreadSigma, 2.5f)
PPR_CONST(float, kTaaSpreadFloor, 0.004f)
// Variance clipping box: mean ± this many standard deviations of the 3×3 neighbourhood (YCoCg).
PPR_CONST(float, kTaaClipSigma, 1.25f)
// taa_average=1, a still pixel: its history averages the jitter cycle, which a single jittered frame's
// neighbourhood spreads around more widely than a moving history's.
PPR_CONST(float, kTaaStillClipSigma, 2.5f)

// --set reproject: how the reflection's own history is fetched (taa_reflection_body.glsl).
PPR_CONST(uint, kReprojectSurface, 0u)     // the surface's motion, as a plain TAA
PPR_CONST(uint, kReprojectCandidates, 1u)  // the smallest of the surface's and reflected point's motion, parallax-scaled
PPR_CONST(uint, kReprojectVirtual, 2u)     // the virtual point's motion (exact for planar reflectors)
// candidates: a motion vector shrinks by this fraction per metre of reflected path (the seed note's
// parallax correction, saturate(1 - length × factor)).
PPR_CONST(float, kTaaParallaxPerMetre, 0.05f)
// virtual: the history is another surface's (disoccluded) when the view depth it stored for its
// virtual point differs from the expected one by more than this fraction.
PPR_CONST(float, kTaaVirtualDepthTolerance, 0.02f)
// taa_moving_edge=1 (virtual): beside a moving draw's reflection, a pixel whose history moved less than
// this (pixels) and was rejected by its own depth, though within the neighbours' reflected depths,
// restarts from the current neighbourhood's mean rather than from its one jittered sample (a faster
// move makes a rejection a trail, which the sharp current sample replaces best).
PPR_CONST(float, kTaaMovingEdgeMotion, 1.0f)
// taa_moving_filter=1: on and beside a moving draw, the current frame enters the blend reconstructed at
// the pixel's centre from the 3×3's jittered samples, weighted exp(−k·d²) by each sample's distance d
// (pixels) from that centre. The Gaussian fit of a Blackman-Harris window is k = 2.29; this narrower one
// scored closer to the supersampled reference on the bobbing ball (docs/temporal.md).
PPR_CONST(float, kTaaMovingFilterSharpness, 4.0f)

PPR_BEGIN
struct TaaReflectionPush {
    uint historyValid;
    uint mode;         // kReproject*
    uint hasDistance;  // 0: the technique gave no path lengths; candidates and virtual use the surface's motion
    float stillSpread;  // taa_still_spread with taa_average: kTaaSpreadSigma, or 0 (off: the 3×3 box alone; the moments image is a stand-in)
    float motionCap;    // taa_reflection_cap with taa_average: kTaaMotionCap, or 0 (off: the feedback alone)
    uint rimKeep;       // taa_rim_keep with taa_average: a moving pixel without a reflection keeps its history (1) or not (0)
    uint stillRange;    // taa_still_range with taa_still_spread: the still run's luma range decides (1), or its moments (0)
    uint stillKeep;     // taa_still_keep with taa_average: a still pixel's history is never rejected by its path's depth (1)
    uint movingEdge;    // taa_moving_edge: a rejected history beside a slow moving draw's reflection restarts from the mean (1)
    // 1: the shown image and the history images were cleared to 0 before the pass (a transfer clear: a
    // memset on a CPU device), so a pixel that would store 0 (no reflection, nothing kept) stores nothing
    uint clearedNone;
};
PPR_END
PPR_SIZE_CHECK(TaaReflectionPush, 40);

PPR_BEGIN
struct TaaPush {
    uint historyValid;  // 0 on the first frame after creation or a reset: the output is the current frame
    // 1: reflector pixels also fetch history where their reflection was (reflection_motion.glsl), mixed
    // in by the composite's reflection weight (reproject=virtual, a technique with reflected paths)
    uint reflectionMotion;
    // split + taa_average: reflectionHistory is bound; a pixel without a reflection this frame takes the
    // one its reflection history kept (a still rim pixel), before a neighbour's
    uint keptReflection;
    float motionCap;  // taa_motion_cap with taa_average: kTaaMotionCap, or 0 (off: the feedback alone)
    float stillSpread;  // taa_still_spread with taa_average: kTaaSpreadSigma, or 0 (off: the 3×3 box alone; the moments image is a stand-in)
    uint stillRange;    // taa_still_range with taa_still_spread: the still run's luma range decides (1), or its moments (0)
    uint movingFilter;  // taa_moving_filter: a moving draw's pixels blend the current frame filtered to their centre (1)
};
PPR_END
PPR_SIZE_CHECK(TaaPush, 28);

#endif
