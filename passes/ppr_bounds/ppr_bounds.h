// PPR reflector bounds pass constants (host/device shared).
#ifndef PPR_BOUNDS_H
#define PPR_BOUNDS_H
#include "shader/shared.h"

PPR_CONST(uint, kPprBoundsGroupSize, 64u)

PPR_BEGIN
struct PprBoundsPush {
    uint reflectorCount;
    uint pad0;
    uint pad1;
    uint pad2;
};
PPR_END
PPR_SIZE_CHECK(PprBoundsPush, 16);

#endif
