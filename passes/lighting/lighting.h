#ifndef PPR_LIGHTING_H
#define PPR_LIGHTING_H
#include "shader/shared.h"
PPR_CONST(uint, kLightingGroupSize, 8u)  // 8x8 threads per workgroup
#endif
