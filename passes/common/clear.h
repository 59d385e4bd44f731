// Compute clears (host/device shared): the push block of clear_float.comp and clear_uint.comp.
#ifndef PPR_CLEAR_H
#define PPR_CLEAR_H
#include "shader/shared.h"

PPR_CONST(uint, kClearGroupSize, 16u)

PPR_BEGIN
struct ClearPush {
    uvec4 value;   // the VkClearColorValue's bits: float images read them with uintBitsToFloat
    uvec2 extent;  // texels to write
    uvec2 pad;
};
PPR_END
PPR_SIZE_CHECK(ClearPush, 32);

#endif
