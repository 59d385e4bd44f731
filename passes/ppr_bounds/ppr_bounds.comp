#version 460
#extension GL_GOOGLE_include_directive : require
#include "common/bindings.glsl"
#include "common/reflector_data.h"
#include "ppr_bounds/ppr_bounds.h"
#include "ppr_common/tile_culling.h"
#include "ppr_common/tiles.h"

// Once per frame, before the projection pass: each reflector's screen rectangle and whether the
// camera may see its reflecting side, so that no tile clips and projects a rectangle again; and the
// reflectors compacted into the frame's lists (PprVisibleCounts), so that every tile's culling and
// the reach pass loop over the reflectors on screen, not over all of them. One workgroup: each
// invocation takes a contiguous run of the projection order, and a scan of the runs' counts ranks
// them, so the lists keep projection order and never depend on thread timing.
layout(local_size_x = kPprBoundsGroupSize) in;
layout(set = 0, binding = 1, scalar) readonly buffer Reflectors { ReflectorData reflectors[]; };
layout(set = 0, binding = 2, scalar) writeonly buffer Bounds { PprReflectorBounds bounds[]; };
layout(set = 0, binding = 3, scalar) readonly buffer Order { uint projectionOrder[]; };
layout(set = 0, binding = 4, scalar) writeonly buffer Visible { PprVisibleCounts visibleCounts; uint visibleLists[]; };
layout(set = 0, binding = 5, scalar) buffer Stats { PprFrameStats stats; };
layout(push_constant, scalar) uniform Push { PprBoundsPush pc; };

shared uint counts[kPprBoundsGroupSize];  // per run: reflecting (low 16 bits) and on screen (high 16)

void main() {
    uint lid = gl_LocalInvocationIndex;
    uint perThread = (pc.reflectorCount + kPprBoundsGroupSize - 1u) / kPprBoundsGroupSize;
    uint first = min(lid * perThread, pc.reflectorCount), last = min(first + perThread, pc.reflectorCount);
    uint reflecting = 0u, onScreen = 0u;  // a bit per reflector of the run
    for (uint k = first; k < last; ++k) {
        uint i = projectionOrder[k];
        PprReflectorBounds b = pprReflectorBounds(reflectors[i], frame.viewProj, frame.cameraPos.xyz, frame.screenSize);
        bounds[i] = b;
        if (!pprRectsOverlap(b.rect, b.rect)) continue;  // an empty rectangle: off screen or behind the camera
        onScreen |= 1u << (k - first);
        if (b.reflects != 0u) reflecting |= 1u << (k - first);
    }
    uint mine = bitCount(reflecting) | (bitCount(onScreen) << 16u);  // ≤ kPprMaxReflectors each: no carry
    counts[lid] = mine;
    barrier();
    // Inclusive scan of the runs' counts (Hillis–Steele: log2 of the group size steps).
    for (uint d = 1u; d < kPprBoundsGroupSize; d <<= 1u) {
        uint add = lid >= d ? counts[lid - d] : 0u;
        barrier();
        counts[lid] += add;
        barrier();
    }
    uint before = counts[lid] - mine;
    uint r = before & 0xFFFFu, s = before >> 16u;
    for (uint k = first; k < last; ++k) {
        uint bit = 1u << (k - first);
        if ((reflecting & bit) != 0u) visibleLists[r++] = projectionOrder[k];
        if ((onScreen & bit) != 0u) visibleLists[pc.reflectorCount + s++] = projectionOrder[k];
    }
    if (lid == kPprBoundsGroupSize - 1u) {
        uint total = counts[lid];
        visibleCounts = PprVisibleCounts(total & 0xFFFFu, total >> 16u, 0u, 0u);
        stats.reflectorsReflecting = total & 0xFFFFu;
        stats.reflectorsOnScreen = total >> 16u;
    }
}
