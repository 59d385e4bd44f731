#version 460
#extension GL_GOOGLE_include_directive : require
#include "common/bindings.glsl"
#include "common/reflector_data.h"
#include "ppr_bounds/ppr_bounds.h"
#include "ppr_common/ordered_float.glsl"
#include "ppr_common/tile_culling.h"
#include "ppr_common/tiles.h"

// Once per frame, before the projection pass: each reflector's screen rectangle and whether the
// camera may see its reflecting side, so that no tile clips and projects a rectangle again; and the
// reflectors compacted into the frame's lists (PprVisibleCounts), so that every tile's culling and
// the reach pass loop over the reflectors on screen, not over all of them. One workgroup: each
// invocation takes a contiguous run of the projection order, and a scan of the runs' counts ranks
// them, so the lists keep projection order and never depend on thread timing. Every run of
// kPprCullChunk candidates gets a summary (PprCullChunk) that lets a tile skip the run unread, and
// so does every run of the on-screen list (after the candidates' summaries). Every cull plane gets
// the bounds of its candidates (PprCullPlaneBounds), which the reach pass tests a tile against when
// there are too many reflectors to test one by one.
layout(local_size_x = kPprBoundsGroupSize) in;
layout(set = 0, binding = 1, scalar) readonly buffer Reflectors { ReflectorData reflectors[]; };
layout(set = 0, binding = 2, scalar) writeonly buffer Bounds { PprReflectorBounds bounds[]; };
layout(set = 0, binding = 3, scalar) readonly buffer Order { uint projectionOrder[]; };
layout(set = 0, binding = 4, scalar) buffer Visible { PPR_VISIBLE_REFLECTORS; };  // read-write: the planes' atomics
layout(set = 0, binding = 5, scalar) buffer Stats { PprFrameStats stats; };
layout(push_constant, scalar) uniform Push { PprBoundsPush pc; };

shared uint counts[kPprBoundsGroupSize];  // per run: reflecting (low 16 bits) and on screen (high 16)
// The run summaries, reduced with atomics, one slot per run of each list as cullChunks holds them
// (the candidates' runs, then the on-screen list's): rectangle corners, box corners as
// order-preserving uints (candidates only), planes, and 1 while every reflector of the run is glass.
const uint kSummaries = 2u * kPprCullChunkCount;
shared uint sumLoX[kSummaries], sumLoY[kSummaries], sumHiX[kSummaries], sumHiY[kSummaries];
shared uvec3 sumBoxLo[kPprCullChunkCount], sumBoxHi[kPprCullChunkCount];
shared uint sumPlaneLo[kSummaries], sumPlaneHi[kSummaries], sumGlass[kSummaries];
shared uint untabled;  // candidates beyond the cull-plane tables

void addToSummary(uint slot, uvec2 rect, ReflectorData reflector) {
    atomicMin(sumLoX[slot], rect.x & 0xFFFFu);
    atomicMin(sumLoY[slot], rect.x >> 16u);
    atomicMax(sumHiX[slot], rect.y & 0xFFFFu);
    atomicMax(sumHiY[slot], rect.y >> 16u);
    atomicMin(sumPlaneLo[slot], reflector.cullPlane);
    atomicMax(sumPlaneHi[slot], reflector.cullPlane);
    if (reflector.kind != kReflectorGlass) atomicAnd(sumGlass[slot], 0u);
}

void addToPlane(uint plane, uvec2 rect, uvec3 boxLo, uvec3 boxHi) {
    if (plane == kPprNoCullPlane) {
        atomicAdd(untabled, 1u);
        return;
    }
    atomicMin(cullPlaneBounds[plane].loX, rect.x & 0xFFFFu);
    atomicMin(cullPlaneBounds[plane].loY, rect.x >> 16u);
    atomicMax(cullPlaneBounds[plane].hiX, rect.y & 0xFFFFu);
    atomicMax(cullPlaneBounds[plane].hiY, rect.y >> 16u);
    atomicMin(cullPlaneBounds[plane].boxLo.x, boxLo.x);
    atomicMin(cullPlaneBounds[plane].boxLo.y, boxLo.y);
    atomicMin(cullPlaneBounds[plane].boxLo.z, boxLo.z);
    atomicMax(cullPlaneBounds[plane].boxHi.x, boxHi.x);
    atomicMax(cullPlaneBounds[plane].boxHi.y, boxHi.y);
    atomicMax(cullPlaneBounds[plane].boxHi.z, boxHi.z);
}

void main() {
    uint lid = gl_LocalInvocationIndex;
    uint perThread = (pc.reflectorCount + kPprBoundsGroupSize - 1u) / kPprBoundsGroupSize;
    uint first = min(lid * perThread, pc.reflectorCount), last = min(first + perThread, pc.reflectorCount);
    uint reflecting = 0u, onScreen = 0u;  // a bit per reflector of the run
    uvec2 rects[kPprMaxReflectors / kPprBoundsGroupSize];  // and its screen rectangle
    for (uint k = first; k < last; ++k) {
        uint i = projectionOrder[k];
        PprReflectorBounds b = pprReflectorBounds(reflectors[i], frame.viewProj, frame.cameraPos.xyz, frame.screenSize);
        bounds[i] = b;
        rects[k - first] = b.rect;
        if (!pprRectsOverlap(b.rect, b.rect)) continue;  // an empty rectangle: off screen or behind the camera
        onScreen |= 1u << (k - first);
        if (b.reflects != 0u) reflecting |= 1u << (k - first);
    }
    uint mine = bitCount(reflecting) | (bitCount(onScreen) << 16u);  // ≤ kPprMaxReflectors each: no carry
    counts[lid] = mine;
    for (uint c = lid; c < kSummaries; c += kPprBoundsGroupSize) {
        sumLoX[c] = sumLoY[c] = sumPlaneLo[c] = 0xFFFFFFFFu;
        sumHiX[c] = sumHiY[c] = sumPlaneHi[c] = 0u;
        sumGlass[c] = 1u;
        if (c < kPprCullChunkCount) {
            sumBoxLo[c] = uvec3(0xFFFFFFFFu);
            sumBoxHi[c] = uvec3(0u);
        }
    }
    for (uint p = lid; p < pc.cullPlaneCount; p += kPprBoundsGroupSize)
        cullPlaneBounds[p] = PprCullPlaneBounds(0xFFFFu, 0xFFFFu, 0u, 0u, uvec3(0xFFFFFFFFu), 0u, uvec3(0u), 0u);
    if (lid == 0u) untabled = 0u;
    memoryBarrierBuffer();  // the planes' bounds are reduced in place below
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
        uint bit = 1u << (k - first), i = projectionOrder[k];
        if ((onScreen & bit) == 0u) continue;
        ReflectorData reflector = reflectors[i];
        uvec2 rect = rects[k - first];
        if ((reflecting & bit) != 0u) {
            uint c = r / kPprCullChunk;
            addToSummary(c, rect, reflector);
            vec3 lo, hi;
            pprRectangleBox(reflector, lo, hi);
            uvec3 l = orderedFromFloat(lo - vec3(kPprCullSlack)), h = orderedFromFloat(hi + vec3(kPprCullSlack));
            atomicMin(sumBoxLo[c].x, l.x);
            atomicMin(sumBoxLo[c].y, l.y);
            atomicMin(sumBoxLo[c].z, l.z);
            atomicMax(sumBoxHi[c].x, h.x);
            atomicMax(sumBoxHi[c].y, h.y);
            atomicMax(sumBoxHi[c].z, h.z);
            addToPlane(reflector.cullPlane, rect, l, h);
            visibleLists[r++] = i;
        }
        addToSummary(kPprCullChunkCount + s / kPprCullChunk, rect, reflector);
        visibleLists[pc.reflectorCount + s++] = i;
    }
    barrier();
    uint total = counts[kPprBoundsGroupSize - 1u];
    for (uint slot = lid; slot < kSummaries; slot += kPprBoundsGroupSize) {
        bool candidates = slot < kPprCullChunkCount;
        uint c = candidates ? slot : slot - kPprCullChunkCount, listed = candidates ? total & 0xFFFFu : total >> 16u;
        if (c * kPprCullChunk >= listed) continue;  // beyond the list: never read
        PprCullChunk chunk;
        chunk.rect = uvec2(sumLoX[slot] | (sumLoY[slot] << 16u), sumHiX[slot] | (sumHiY[slot] << 16u));
        chunk.boxLo = candidates ? floatFromOrdered(sumBoxLo[c]) : vec3(0.0);
        chunk.boxHi = candidates ? floatFromOrdered(sumBoxHi[c]) : vec3(0.0);
        chunk.cullPlane = sumPlaneLo[slot] == sumPlaneHi[slot] ? sumPlaneLo[slot] : kPprNoCullPlane;
        chunk.allGlass = candidates ? 0u : sumGlass[slot];
        cullChunks[slot] = chunk;
    }
    if (lid == kPprBoundsGroupSize - 1u) {
        visibleCounts = PprVisibleCounts(total & 0xFFFFu, total >> 16u, untabled, 0u);
        stats.reflectorsReflecting = total & 0xFFFFu;
        stats.reflectorsOnScreen = total >> 16u;
    }
}
