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
// so does every run of the on-screen list (after the candidates' summaries).
layout(local_size_x = kPprBoundsGroupSize) in;
layout(set = 0, binding = 1, scalar) readonly buffer Reflectors { ReflectorData reflectors[]; };
layout(set = 0, binding = 2, scalar) writeonly buffer Bounds { PprReflectorBounds bounds[]; };
layout(set = 0, binding = 3, scalar) readonly buffer Order { uint projectionOrder[]; };
layout(set = 0, binding = 4, scalar) writeonly buffer Visible { PPR_VISIBLE_REFLECTORS; };
layout(set = 0, binding = 5, scalar) buffer Stats { PprFrameStats stats; };
layout(push_constant, scalar) uniform Push { PprBoundsPush pc; };

shared uint counts[kPprBoundsGroupSize];  // per run: reflecting (low 16 bits) and on screen (high 16)
// Per culling chunk, reduced with atomics: rectangle corners, box corners as order-preserving uints, planes.
shared uint chunkLoX[kPprCullChunkCount], chunkLoY[kPprCullChunkCount], chunkHiX[kPprCullChunkCount], chunkHiY[kPprCullChunkCount];
shared uvec3 chunkBoxLo[kPprCullChunkCount], chunkBoxHi[kPprCullChunkCount];
shared uint chunkPlaneLo[kPprCullChunkCount], chunkPlaneHi[kPprCullChunkCount];
// The same for the on-screen list's runs (no boxes), and 1 while every reflector of the run is glass.
shared uint seenLoX[kPprCullChunkCount], seenLoY[kPprCullChunkCount], seenHiX[kPprCullChunkCount], seenHiY[kPprCullChunkCount];
shared uint seenPlaneLo[kPprCullChunkCount], seenPlaneHi[kPprCullChunkCount], seenGlass[kPprCullChunkCount];

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
    for (uint c = lid; c < kPprCullChunkCount; c += kPprBoundsGroupSize) {
        chunkLoX[c] = chunkLoY[c] = chunkPlaneLo[c] = 0xFFFFFFFFu;
        chunkHiX[c] = chunkHiY[c] = chunkPlaneHi[c] = 0u;
        chunkBoxLo[c] = uvec3(0xFFFFFFFFu);
        chunkBoxHi[c] = uvec3(0u);
        seenLoX[c] = seenLoY[c] = seenPlaneLo[c] = 0xFFFFFFFFu;
        seenHiX[c] = seenHiY[c] = seenPlaneHi[c] = 0u;
        seenGlass[c] = 1u;
    }
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
            vec3 lo, hi;
            pprRectangleBox(reflector, lo, hi);
            atomicMin(chunkLoX[c], rect.x & 0xFFFFu);
            atomicMin(chunkLoY[c], rect.x >> 16u);
            atomicMax(chunkHiX[c], rect.y & 0xFFFFu);
            atomicMax(chunkHiY[c], rect.y >> 16u);
            uvec3 l = orderedFromFloat(lo - vec3(kPprCullSlack)), h = orderedFromFloat(hi + vec3(kPprCullSlack));
            atomicMin(chunkBoxLo[c].x, l.x);
            atomicMin(chunkBoxLo[c].y, l.y);
            atomicMin(chunkBoxLo[c].z, l.z);
            atomicMax(chunkBoxHi[c].x, h.x);
            atomicMax(chunkBoxHi[c].y, h.y);
            atomicMax(chunkBoxHi[c].z, h.z);
            atomicMin(chunkPlaneLo[c], reflector.cullPlane);
            atomicMax(chunkPlaneHi[c], reflector.cullPlane);
            visibleLists[r++] = i;
        }
        uint c = s / kPprCullChunk;
        atomicMin(seenLoX[c], rect.x & 0xFFFFu);
        atomicMin(seenLoY[c], rect.x >> 16u);
        atomicMax(seenHiX[c], rect.y & 0xFFFFu);
        atomicMax(seenHiY[c], rect.y >> 16u);
        atomicMin(seenPlaneLo[c], reflector.cullPlane);
        atomicMax(seenPlaneHi[c], reflector.cullPlane);
        if (reflector.kind != kReflectorGlass) atomicAnd(seenGlass[c], 0u);
        visibleLists[pc.reflectorCount + s++] = i;
    }
    barrier();
    uint total = counts[kPprBoundsGroupSize - 1u];
    for (uint c = lid; c * kPprCullChunk < (total & 0xFFFFu); c += kPprBoundsGroupSize) {
        PprCullChunk chunk;
        chunk.rect = uvec2(chunkLoX[c] | (chunkLoY[c] << 16u), chunkHiX[c] | (chunkHiY[c] << 16u));
        chunk.boxLo = floatFromOrdered(chunkBoxLo[c]);
        chunk.boxHi = floatFromOrdered(chunkBoxHi[c]);
        chunk.cullPlane = chunkPlaneLo[c] == chunkPlaneHi[c] ? chunkPlaneLo[c] : kPprNoCullPlane;
        chunk.allGlass = 0u;
        cullChunks[c] = chunk;
    }
    for (uint c = lid; c * kPprCullChunk < (total >> 16u); c += kPprBoundsGroupSize) {
        PprCullChunk chunk;
        chunk.rect = uvec2(seenLoX[c] | (seenLoY[c] << 16u), seenHiX[c] | (seenHiY[c] << 16u));
        chunk.boxLo = vec3(0.0);
        chunk.boxHi = vec3(0.0);
        chunk.cullPlane = seenPlaneLo[c] == seenPlaneHi[c] ? seenPlaneLo[c] : kPprNoCullPlane;
        chunk.allGlass = seenGlass[c];
        cullChunks[kPprCullChunkCount + c] = chunk;
    }
    if (lid == kPprBoundsGroupSize - 1u) {
        visibleCounts = PprVisibleCounts(total & 0xFFFFu, total >> 16u, 0u, 0u);
        stats.reflectorsReflecting = total & 0xFFFFu;
        stats.reflectorsOnScreen = total >> 16u;
    }
}
