// PPR reflector bounds pass constants (host/device shared).
#ifndef PPR_BOUNDS_H
#define PPR_BOUNDS_H
#include "shader/shared.h"

// One workgroup compacts every reflector in projection order: each invocation takes a run of
// kPprMaxReflectors / kPprBoundsGroupSize at most (4), judged into one bit mask per list.
PPR_CONST(uint, kPprBoundsGroupSize, 256u)

PPR_BEGIN
struct PprBoundsPush {
    uint reflectorCount;
    uint cullPlaneCount;  // ≤ kPprMaxCullPlanes
    uint pad0;
    uint pad1;
};
PPR_END
PPR_SIZE_CHECK(PprBoundsPush, 16);

#endif
