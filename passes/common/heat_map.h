// The reflection-error heat map, shared by `ppr compare` (app/compare_metrics.cpp) and the viewer's
// A/B heat view (passes/ab_compare): the same colours for the same error (host/device shared).
#ifndef PPR_HEAT_MAP_H
#define PPR_HEAT_MAP_H
#include "shader/shared.h"

// Display-space error drawn white; smaller errors run black → red → yellow → white in equal thirds.
PPR_CONST(float, kErrorHeatFullScale, 0.25f)

PPR_BEGIN
PPR_INLINE vec3 errorHeatColor(float error) {
    float t = clamp(error / kErrorHeatFullScale, 0.0f, 1.0f) * 3.0f;
    return vec3(clamp(t, 0.0f, 1.0f), clamp(t - 1.0f, 0.0f, 1.0f), clamp(t - 2.0f, 0.0f, 1.0f));
}
PPR_END

#endif
