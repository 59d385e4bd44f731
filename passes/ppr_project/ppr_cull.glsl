// PPR projection, per-tile culling (tiles=1): the survivor and occluder lists of a tile, and the plane
// grid where its survivors share one plane (docs/architecture.md, "Per-tile culling"). Included by
// ppr_project.comp, which declares the bindings, the push constants and the shared lists used here.
#include "ppr_common/plane_grid.h"
#include "ppr_common/tile_culling.h"

// The cull plane whose grid the tile's pixels use (kPprNoCullPlane: none), the same in every thread.
uint gridPlane = kPprNoCullPlane;
PprPlaneGrid grid;
vec3 gridLeaderCenter, gridLeaderNormal;  // the plane the grid's pixels mirror themselves in

// Builds this tile's survivor and occluder lists. Called by every thread (uniform control flow).
void cullReflectors(vec3 lo, vec3 hi) {
    uint lid = gl_LocalInvocationIndex;
    // The tile mirrored once per cull plane.
    for (uint base = 0u; base < pc.cullPlaneCount; base += kThreads) {
        uint plane = base + lid;
        if (plane < pc.cullPlaneCount) {
            ReflectorData leader = reflectors[planeLeaders[plane]];
            planeRect[plane] = pprTileReflectedRect(lo, hi, leader.normal, leader.center, frame.viewProj, frame.screenSize);
            vec3 l, h;
            pprTileHitRegion(lo, hi, leader.normal, leader.center, frame.cameraPos.xyz, l, h);
            hitLo[plane] = l;
            hitHi[plane] = h;
        }
    }
    barrier();
    // Survivors in projection order, in one phase: each invocation judges a contiguous run of the
    // order (at most 32 reflectors: kPprMaxReflectors / kThreads) into a bit mask, and its first
    // survivor's rank is the number of survivors in the runs before it, so the list never depends
    // on thread timing and the workgroup meets at one barrier whatever the reflector count.
    uint candidates = visibleCounts.reflecting;  // on screen, reflecting side seen, in projection order
    uint perThread = (candidates + kThreads - 1u) / kThreads;
    uint first = min(lid * perThread, candidates), last = min(first + perThread, candidates);
    uint verdicts = 0u;
    uvec4 reachMine = uvec4(0xFFFFu, 0xFFFFu, 0u, 0u);  // lo x, lo y, hi x, hi y
    uvec2 planesMine = uvec2(kPprNoCullPlane, 0u);
    for (uint k = first; k < last; ++k) {
        if (k == first || k % kPprCullChunk == 0u) {  // entering a chunk: skip it whole when its summary rules it out
            PprCullChunk chunk = cullChunks[k / kPprCullChunk];
            uint plane = chunk.cullPlane == kPprNoCullPlane ? 0u : chunk.cullPlane;
            if (!pprTileMayReachChunk(chunk, planeRect[plane], hitLo[plane], hitHi[plane])) {
                k = min(last, (k / kPprCullChunk + 1u) * kPprCullChunk) - 1u;
                continue;
            }
        }
        uint i = visibleLists[k];
        PprReflectorBounds b = bounds[i];
        ReflectorData r = reflectors[i];
        // Reflectors beyond the per-plane tables are judged on their own rectangle alone.
        bool tabled = r.cullPlane != kPprNoCullPlane;
        uint plane = tabled ? r.cullPlane : 0u;  // untabled: the tables are not read by the verdict
        uvec2 mirrored = tabled ? planeRect[plane] : b.rect;
        if (!pprTileMayReachReflector(r, b, mirrored, hitLo[plane], hitHi[plane])) continue;
        verdicts |= 1u << (k - first);
        planesMine = uvec2(min(planesMine.x, r.cullPlane), max(planesMine.y, r.cullPlane));
        // It can only write where both rectangles overlap.
        reachMine = uvec4(min(reachMine.xy, uvec2(max(mirrored.x & 0xFFFFu, b.rect.x & 0xFFFFu), max(mirrored.x >> 16u, b.rect.x >> 16u))),
                          max(reachMine.zw, uvec2(min(mirrored.y & 0xFFFFu, b.rect.y & 0xFFFFu), min(mirrored.y >> 16u, b.rect.y >> 16u))));
    }
    uint mine = bitCount(verdicts);
    runSurvivors[lid] = mine;
    // Where every subgroup holds consecutive invocations in order (the devices we know), a subgroup
    // scan and one sum per subgroup give the ranks; otherwise each invocation adds up the runs before it.
    uint beforeInSubgroup = subgroupExclusiveAdd(mine), subgroupTotal = subgroupAdd(mine);
    if (subgroupElect()) subgroupSurvivors[gl_SubgroupID] = subgroupTotal;
    if (gl_SubgroupID * gl_SubgroupSize + gl_SubgroupInvocationID != lid) atomicOr(scatteredSubgroups, 1u);
    if (verdicts != 0u) {
        atomicMin(reachLoX, reachMine.x);
        atomicMin(reachLoY, reachMine.y);
        atomicMax(reachHiX, reachMine.z);
        atomicMax(reachHiY, reachMine.w);
        atomicMin(survivorPlaneLo, planesMine.x);
        atomicMax(survivorPlaneHi, planesMine.y);
    }
    barrier();
    uint rank = 0u, total = 0u;
    if (scatteredSubgroups == 0u) {
        for (uint g = 0u; g < gl_NumSubgroups; ++g) {
            if (g < gl_SubgroupID) rank += subgroupSurvivors[g];
            total += subgroupSurvivors[g];
        }
        rank += beforeInSubgroup;
    } else {
        for (uint t = 0u; t < kThreads; ++t) {
            if (t < lid) rank += runSurvivors[t];
            total += runSurvivors[t];
        }
    }
    for (uint bits = verdicts; bits != 0u; bits &= bits - 1u, ++rank) {
        uint i = visibleLists[first + uint(findLSB(bits))];
        atomicOr(survivorWords[rank >> 1u], i << (16u * (rank & 1u)));  // neighbouring runs may share a word
    }
    if (lid == 0u) survivorCount = total;
    barrier();
    // With all survivors in one cull plane, and enough of them, pixels look them up in a grid.
    uint sharedPlane = survivorPlaneLo == survivorPlaneHi ? survivorPlaneLo : kPprNoCullPlane;
    gridPlane = sharedPlane != kPprNoCullPlane && survivorCount >= kPprPlaneGridMinSurvivors &&
                survivorCount <= kPprPlaneGridMaxSurvivors ? sharedPlane : kPprNoCullPlane;  // uniform
    if (gridPlane != kPprNoCullPlane)
        for (uint w = lid; w < kPprPlaneGridSize * kPprPlaneGridSize * kPprPlaneGridWords; w += kThreads) gridWords[w] = 0u;
    // Possible occluders: every reflector on screen (either side facing) whose screen rectangle meets
    // the pixels the survivors can write to.
    // Glass occludes nothing, and where every survivor lies in one cull plane a reflector of that plane
    // cannot either: the segment eye → hit ends in its plane (the per-pixel test's t ≈ 1, which it
    // rejects), so neither is gathered. That keeps a floor of coplanar tiles from testing its neighbours.
    uvec2 reach = uvec2(reachLoX | (reachLoY << 16u), reachHiX | (reachHiY << 16u));
    // Runs of the on-screen list whose summary rules them all out are skipped unread.
    uint onScreen = survivorCount > 0u ? visibleCounts.onScreen : 0u;  // no survivor, nothing to occlude
    for (uint c = lid; c * kPprCullChunk < onScreen; c += kThreads) {
        PprCullChunk chunk = cullChunks[kPprCullChunkCount + c];
        if (!pprRectsOverlap(chunk.rect, reach) || chunk.allGlass != 0u || (sharedPlane != kPprNoCullPlane && chunk.cullPlane == sharedPlane))
            continue;
        for (uint k = c * kPprCullChunk; k < min(onScreen, (c + 1u) * kPprCullChunk); ++k) {
            uint j = visibleLists[pc.reflectorCount + k];
            if (pprRectsOverlap(bounds[j].rect, reach) && reflectors[j].kind != kReflectorGlass &&
                (sharedPlane == kPprNoCullPlane || reflectors[j].cullPlane != sharedPlane)) {
                uint slot = atomicAdd(occluderCount, 1u);
                atomicOr(occluderWords[slot >> 1u], j << (16u * (slot & 1u)));
            }
        }
    }
    barrier();
    if (gridPlane != kPprNoCullPlane) {
        ReflectorData leader = reflectors[planeLeaders[gridPlane]];
        grid = pprPlaneGridOver(hitLo[gridPlane], hitHi[gridPlane], leader.tangent, leader.bitangent);
        gridLeaderCenter = leader.center;
        gridLeaderNormal = leader.normal;
        for (uint k = lid; k < survivorCount; k += kThreads) {
            uvec4 cells = pprPlaneGridCellsOf(grid, reflectors[survivorAt(k)]);
            for (uint y = cells.y; y <= cells.w; ++y)
                for (uint x = cells.x; x <= cells.z; ++x)
                    atomicOr(gridWords[(x + y * kPprPlaneGridSize) * kPprPlaneGridWords + (k >> 5u)], 1u << (k & 31u));
        }
        barrier();
    }
}
