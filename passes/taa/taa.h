// Temporal anti-aliasing (host/device shared): the resolve's constants and push block.
#ifndef PPR_TAA_H
#define PPR_TAA_H
#include "shader/shared.h"

PPR_CONST(uint, kTaaGroupSize, 16u)
// Weight of the history: between these, by how much the current and the clipped history's luma agree
// (a large difference is a change the history has not seen yet, so it keeps less of it).
PPR_CONST(float, kTaaFeedbackMin, 0.88f)
PPR_CONST(float, kTaaFeedbackMax, 0.97f)
// Variance clipping box: mean ± this many standard deviations of the 3×3 neighbourhood (YCoCg).
PPR_CONST(float, kTaaClipSigma, 1.25f)

PPR_BEGIN
struct TaaPush {
    uint historyValid;  // 0 on the first frame after creation or a reset: the output is the current frame
    uint pad0, pad1, pad2;
};
PPR_END
PPR_SIZE_CHECK(TaaPush, 16);

#endif
