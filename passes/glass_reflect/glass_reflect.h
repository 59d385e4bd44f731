// The glass atlas's reflection pass (host/device shared).
#ifndef PPR_GLASS_REFLECT_H
#define PPR_GLASS_REFLECT_H
#include "shader/shared.h"

PPR_CONST(uint, kGlassReflectGroupSize, 16u)

PPR_BEGIN
struct GlassReflectPush {
    uint regionCount;  // entries of the region list
    uint flags;        // ppr_reflect.h kPprHoleFilling | kPprFiltering | kPprAntiBleeding
    uint pad0, pad1;
};
PPR_END
PPR_SIZE_CHECK(GlassReflectPush, 16);

#endif
