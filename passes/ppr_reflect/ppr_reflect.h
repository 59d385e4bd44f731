// PPR reflection pass constants (host/device shared).
#ifndef PPR_REFLECT_H
#define PPR_REFLECT_H
#include "shader/shared.h"

PPR_CONST(uint, kPprReflectGroupSize, 8u)
// Toggles (--set holes / filter / antibleed).
PPR_CONST(uint, kPprHoleFilling, 1u)
PPR_CONST(uint, kPprFiltering, 2u)
PPR_CONST(uint, kPprAntiBleeding, 4u)
// Hole filling replaces a pixel's own data only when a neighbour's offset is this much shorter
// (pixels; the slides' value).
PPR_CONST(float, kPprHoleMinDistance, 6.0f)

PPR_BEGIN
struct PprReflectPush {
    uint flags;      // kPprHoleFilling | kPprFiltering | kPprAntiBleeding
    uint debugView;  // frame.h kDebug*: intermediate and holes are drawn here
    uint pad0;
    uint pad1;
};
PPR_END
PPR_SIZE_CHECK(PprReflectPush, 16);

#endif
