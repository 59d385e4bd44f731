// Planar ground truth constants (host/device shared).
#ifndef PPR_PLANAR_H
#define PPR_PLANAR_H
#include "shader/shared.h"

PPR_CONST(uint, kPlanarGroupSize, 8u)
// The reflected point counts as visible in the main view when the main view's surface at its screen
// position lies within this distance of it (metres, plus a fraction of its distance to the camera).
PPR_CONST(float, kPlanarVisibleTolerance, 0.01f)
PPR_CONST(float, kPlanarVisibleTolerancePerMetre, 0.004f)

// What the reference knows of each reflected point, for `ppr compare`'s error classes
// (app/metrics/error_breakdown.hpp): planar.distance, a reflected-path image (common/reflection.h):
// x = length of the reflected path, y = a tag whose class bits are kPlanarParallelShape.
// The reflected point also lies above a nearer parallel reflector that reflects it to the eye: PPR
// writes a point into the nearest such shape only, so this pixel has to come from hole filling.
PPR_CONST(uint, kPlanarParallelShape, 1u)

PPR_BEGIN
struct PlanarResolvePush {
    uint planeGroup;  // reflectors of this plane group take their reflection from this mirrored view
    uint reflectorCount;
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
