// The viewer's A/B comparison with the planar ground truth (host/device shared).
#ifndef PPR_AB_COMPARE_H
#define PPR_AB_COMPARE_H
#include "shader/shared.h"

PPR_CONST(uint, kAbSplit, 0u)  // reflection: the technique's left of splitX, the reference's right of it
PPR_CONST(uint, kAbHeat, 1u)   // over the frame: the reflection error on the reference's scored pixels

PPR_BEGIN
struct AbComparePush {
    uint mode;     // kAbSplit | kAbHeat
    float splitX;  // pixels
    uint pad0, pad1;
};
PPR_END
PPR_SIZE_CHECK(AbComparePush, 16);

#endif
