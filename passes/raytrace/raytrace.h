// The ray-traced reference (technique `raytraced`), host/device shared: constants and push blocks of
// the screen pass (raytrace_reflect.comp) and the glass-atlas pass (raytrace_glass.comp).
#ifndef PPR_RAYTRACE_H
#define PPR_RAYTRACE_H
#include "shader/shared.h"

PPR_CONST(uint, kRaytraceGroupSize, 8u)
// Flags
PPR_CONST(uint, kRaytraceNormalMapped, 1u)  // reflect about the G-buffer's normal-mapped normal, not the reflector's plane
PPR_CONST(uint, kRaytraceWriteDistance, 2u)  // write each pixel's reflected path length (TAA's virtual point; 0 = none)
// Hits closer to the reflector's plane than this (metres) are ignored: the planar reference's mirrored
// views clip at the plane raised by the same distance (scene::mirrorView's clipOffset), so that
// surfaces lying on the plane never reflect themselves.
PPR_CONST(float, kRaytraceClipOffset, 2e-3f)

PPR_BEGIN
struct RaytracePush {
    uint flags;        // kRaytrace*
    uint looseCount;   // reflectors no mesh belongs to, tested at each hit (gbuffer/gbuffer.h)
    uint regionCount;  // glass pass: entries of the region list
    uint subpixelBits; // rt_coverage=raster (the pipelines' constant kRasterCoverage): the device's subPixelPrecisionBits
};
PPR_END
PPR_SIZE_CHECK(RaytracePush, 16);

#endif
