// Planar ground truth constants (host/device shared).
#ifndef PPR_PLANAR_H
#define PPR_PLANAR_H
#include "shader/shared.h"

PPR_CONST(uint, kPlanarGroupSize, 8u)
// The reflected point counts as visible in the main view when the main view's surface at its screen
// position lies within this distance of it (metres, plus a fraction of its distance to the camera).
PPR_CONST(float, kPlanarVisibleTolerance, 0.01f)
PPR_CONST(float, kPlanarVisibleTolerancePerMetre, 0.004f)

PPR_BEGIN
struct PlanarResolvePush {
    uint planeGroup;  // reflectors of this plane group take their reflection from this mirrored view
    uint pad0;
    uint pad1;
    uint pad2;
};
PPR_END
PPR_SIZE_CHECK(PlanarResolvePush, 16);

PPR_BEGIN
struct PlanarGlassPush {
    uint planeGroup;   // glass panels of this plane group take their reflection from this mirrored view
    uint regionCount;  // entries of the glass region list
    uint pad0;
    uint pad1;
};
PPR_END
PPR_SIZE_CHECK(PlanarGlassPush, 16);

#endif
