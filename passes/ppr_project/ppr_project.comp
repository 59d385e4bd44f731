#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_KHR_shader_subgroup_basic : require
#extension GL_KHR_shader_subgroup_arithmetic : require
#include "common/bindings.glsl"
#include "common/reflector_data.h"
#include "ppr_common/encoding.h"
#include "ppr_common/ordered_float.glsl"
#include "ppr_common/plane_grid.h"
#include "ppr_common/tile_box.h"
#include "ppr_common/tile_culling.h"
#include "ppr_common/tiles.h"
#include "ppr_project/ppr_project.h"
#include "ppr_reach/ppr_reach.h"
#include "glass_forward/glass_forward.h"

// PPR step 2, the projection pass: every pixel finds the reflectors that reflect it and scatters
// its screen-space offset to where it appears in them, keeping the closest with imageAtomicMin. One
// workgroup per screen tile: every tile, or with culling and indirect dispatch only the tiles the
// reach pass listed (ppr_reach.comp: the rest would keep no reflector). Each invocation
// reconstructs the world positions of its pixels once and keeps them in registers; the tile's
// bounds come with the reach pass's list, or without one are built here as the reach pass builds
// them (ppr_common/tile_box.h; one shared atomic per subgroup and value). With culling on, the
// workgroup then tests every reflector against the tile's bounds in parallel (ppr_cull.glsl,
// ppr_common/tile_culling.h), skipping runs of them whose summary rules them out, and keeps, in
// shared memory and in projection order, the survivors and the possible occluders; each pixel then
// runs the per-reflector logic over those lists only, or, where the survivors share one plane, over
// those of its cells in a grid over that plane (ppr_common/plane_grid.h); an invocation runs over
// the candidates once for all its pixels (projectTile). The tests run over the frame's reflectors
// on screen (the bounds pass's lists), not over all of them. With culling off the lists are all
// reflectors.
// A pixel whose chosen reflector magnifies its surface also fills the cell between its landing and
// its neighbours' (splat=1, ppr_splat.glsl).
// kThreads invocations per tile, each projecting every kThreads-th pixel: a specialization constant
// (--set project_threads), since the best count depends on the device (ppr_project.h).
layout(local_size_x_id = 0) in;
layout(constant_id = 0) const uint kThreads = kPprProjectThreads;  // PprProjectPass always specialises it
layout(set = 0, binding = 1) uniform sampler2D depthTex;
layout(set = 0, binding = 2, scalar) readonly buffer Reflectors { ReflectorData reflectors[]; };
layout(set = 0, binding = 3, scalar) readonly buffer Order { uint projectionOrder[]; };
layout(set = 0, binding = 4, r32ui) uniform uimage2D intermediate;
layout(set = 0, binding = 5, scalar) readonly buffer Bounds { PprReflectorBounds bounds[]; };
layout(set = 0, binding = 6, scalar) writeonly buffer TileSurvivors { uint tileSurvivors[]; };
layout(set = 0, binding = 7, scalar) buffer Stats { PprFrameStats stats; };
layout(set = 0, binding = 8, scalar) readonly buffer PlaneLeaders { uint planeLeaders[]; };  // a reflector per cull plane
// Glass panels: their own intermediate buffer, an atlas with one region per visible panel this frame.
layout(set = 0, binding = 9, r32ui) uniform uimage2D glassAtlas;
layout(set = 0, binding = 10, scalar) readonly buffer GlassRegions { GlassRegionData glassRegions[]; };  // per reflector
layout(set = 0, binding = 11) uniform sampler2D normalTex;  // G-buffer normal (pc.facingOnly)
layout(set = 0, binding = 12, scalar) readonly buffer ReachTiles { PprReachedTile reachTiles[]; };  // pc.tileList: the tiles to project
layout(set = 0, binding = 13, scalar) readonly buffer Visible { PPR_VISIBLE_REFLECTORS; };
layout(push_constant, scalar) uniform Push { PprProjectPush pc; };

const uint kPixelsPerThread = kPprTileSize * kPprTileSize / kThreads;

// Tile bounds as order-preserving uints so that integer min/max reduce floats exactly, and the
// least depth of the tile's points (tile_box.h; the bits of a positive float).
shared uvec3 boxLo, boxHi;
shared uint boxLeastDepth;

shared uvec2 planeRect[kPprMaxCullPlanes];          // per cull plane: the tile's mirrored screen rectangle
shared vec3 hitLo[kPprMaxCullPlanes], hitHi[kPprMaxCullPlanes];  // and its hit region
shared uint survivorWords[kPprMaxReflectors / 2u];  // 16-bit reflector indices, in projection order
shared uint occluderWords[kPprMaxReflectors / 2u];  // 16-bit reflector indices, in any order
shared uint runSurvivors[kThreads];  // survivors in each invocation's run of the projection order
shared uint subgroupSurvivors[kThreads];  // their sums per subgroup (gl_SubgroupID)
shared uint scatteredSubgroups;           // 1 if some subgroup is not a consecutive run of invocations
shared uint survivorCount, occluderCount;
shared uint reachLoX, reachLoY, reachHiX, reachHiY;  // pixels the survivors can write to
shared uint survivorPlaneLo, survivorPlaneHi;        // the least and greatest cull plane among the survivors
// Point location where all survivors share one cull plane (ppr_common/plane_grid.h): per cell, one
// bit per survivor rank whose rectangle may reach into it.
shared uint gridWords[kPprPlaneGridSize * kPprPlaneGridSize * kPprPlaneGridWords];

uint unpack16(uint word, uint slot) { return (word >> (16u * (slot & 1u))) & 0xFFFFu; }
uint survivorAt(uint k) { return pc.cullTiles == 0u ? projectionOrder[k] : unpack16(survivorWords[k >> 1u], k); }
uint occluderAt(uint k) { return pc.cullTiles == 0u ? k : unpack16(occluderWords[k >> 1u], k); }

// Occluding shapes: does the segment eye → hit cross another reflector's rectangle first? Coplanar
// neighbours meet the segment at its end and do not count. Only a reflector whose screen rectangle
// holds the written pixel (`landed`) can cross that segment (it projects to that one point), so the
// tile's occluder list is enough, and a reflector whose rectangle (grown by kPprCullMarginPx) misses
// that pixel is passed by without reading the rest of it. Glass lets the view through: it occludes
// nothing.
bool occludedByOtherReflector(vec3 eye, vec3 hit, uint self, uint candidates, uvec2 landed) {
    vec3 d = hit - eye;
    for (uint k = 0u; k < candidates; ++k) {
        uint j = occluderAt(k);
        if (j == self || !pprRectContains(bounds[j].rect, landed)) continue;
        ReflectorData o = reflectors[j];
        if (o.kind == kReflectorGlass) continue;
        float denom = dot(d, o.normal);
        if (abs(denom) < 1e-8) continue;
        float t = dot(o.center - eye, o.normal) / denom;
        if (t > 1e-4 && t < 1.0 - 1e-4 && reflectorContains(o, eye + d * t)) return true;
    }
    return false;
}

// Where the mirror image lands (`target`, pixels); false behind the camera or off screen.
bool landing(vec3 mirrored, out vec2 target) {
    vec4 clip = frame.viewProj * vec4(mirrored, 1.0);
    if (clip.w <= 0.0) return false;
    vec2 ndc = clip.xy / clip.w;
    if (any(greaterThanEqual(abs(ndc), vec2(1.0)))) return false;
    target = (ndc * 0.5 + 0.5) * frame.screenSize;
    return true;
}

// Writes the pixel's offset where its mirror image lands; false when it does not fit.
bool writeOffset(ivec2 pix, vec2 target) {
    uint value;
    if (!pprEncode(target - (vec2(pix) + 0.5), value)) return false;  // beyond the 12-bit range: dropped, not wrapped
    imageAtomicMin(intermediate, ivec2(target), value);
    return true;
}

#include "ppr_project/ppr_splat.glsl"

// A glass panel's data goes to its atlas region, at the texel under the written pixel; the offset
// stays in screen pixels. No occlusion test: whatever hides the panel is the glass pass's depth test.
void writeGlassOffset(ivec2 pix, vec3 mirrored, uint panel) {
    GlassRegionData region = glassRegions[panel];
    vec4 clip = frame.viewProj * vec4(mirrored, 1.0);
    if (clip.w <= 0.0 || region.valid == 0u) return;
    vec2 target = pixelFromClip(clip);
    ivec2 texel = ivec2(floor(glassAtlasFromScreen(region, target)));
    ivec2 lo = ivec2(region.atlasOrigin), hi = lo + ivec2(region.atlasSize);
    if (any(lessThan(texel, lo)) || any(greaterThanEqual(texel, hi))) return;  // never into another region
    uint value;
    if (!pprEncode(target - (vec2(pix) + 0.5), value)) return;
    imageAtomicMin(glassAtlas, texel, value);
}

#include "ppr_project/ppr_cull.glsl"

// The screen tile this workgroup projects: its id, or with the reach pass's list, the id-th listed tile.
uvec2 tile;

// This invocation's j-th pixel of the tile.
ivec2 pixelOf(uint j) {
    uint i = gl_LocalInvocationIndex + j * kThreads;
    return ivec2(tile) * int(kPprTileSize) + ivec2(i % kPprTileSize, i / kPprTileSize);
}

// Does reflector r take the pixel at p, nearer than bestDistance? Its height d above r's plane, its
// mirror image and where the ray from the eye to that image crosses the plane (the hit, which r's
// rectangle must hold). Not when the pixel is not above the plane, the camera sees r from behind, or
// (facing=1) the mirrored eye sees the surface from behind. `facing`: with facing=1, the cosine between
// the surface normal and the direction to the mirrored eye (splatMagnified's estimate); else 2.
bool takes(ReflectorData r, vec3 p, vec3 eye, vec3 surfaceNormal, float above, float bestDistance, out float d, out vec3 mirrored,
           out vec3 hit, out float facing) {
    facing = 2.0;
    d = dot(p - r.center, r.normal);
    if (d <= above || d >= bestDistance) return false;  // not above this plane, or a nearer parallel shape won
    float eyeHeight = dot(eye - r.center, r.normal);
    if (eyeHeight <= 0.0) return false;  // the camera sees this reflector from behind
    mirrored = p - 2.0 * d * r.normal;
    if (pc.facingOnly != 0u) {  // seen from behind by the mirrored eye: hidden in this reflection
        vec3 mirroredEye = eye - 2.0 * eyeHeight * r.normal;
        facing = dot(surfaceNormal, normalize(mirroredEye - p));
        if (facing < kPprFacingCos) return false;
    }
    // Ray from the camera to the mirrored point crosses the plane at eyeHeight / (eyeHeight + d).
    hit = mix(eye, mirrored, eyeHeight / (eyeHeight + d));
    return reflectorContains(r, hit);
}

// The reflector chosen for a pixel writes its offset: glass into its atlas region, others where no
// other reflector hides the hit.
void writeChosen(ivec2 pix, vec3 p, vec3 surfaceNormal, vec3 eye, uint best, vec3 mirrored, vec3 hit, float facing, uint occluders) {
    if (reflectors[best].kind == kReflectorGlass) {
        writeGlassOffset(pix, mirrored, best);
        return;
    }
    vec2 target;
    if (landing(mirrored, target) && !occludedByOtherReflector(eye, hit, best, occluders, uvec2(target)) && writeOffset(pix, target) &&
        pc.splat != 0u)
        splatMagnified(pix, p, surfaceNormal, best, mirrored, facing, target);
}

// A glass reflector without an atlas region this frame takes no pixels.
bool skipped(ReflectorData r, uint i) { return r.kind == kReflectorGlass && (pc.glass == 0u || glassRegions[i].valid == 0u); }

// The choices of this invocation's pixels in the current orientation group (projectTile): the
// nearest reflector taking each so far (kPprNoChoice: none) and its plane distance (kPprUnbounded: none).
const uint kPprNoChoice = 0xFFFFFFFFu;
const float kPprUnbounded = 3.4e38;
uint chosen[kPixelsPerThread];
float chosenDistance[kPixelsPerThread];

// Every pixel that chose a reflector in the current group writes its offset, and the choices
// restart. The mirror image, hit and facing are those `takes` found when it chose (the same code).
void writeChoices(vec4 points[kPixelsPerThread], vec3 normals[kPixelsPerThread], float above[kPixelsPerThread], vec3 eye,
                  uint occluders) {
    for (uint j = 0u; j < kPixelsPerThread; ++j) {
        uint best = chosen[j];
        chosen[j] = kPprNoChoice;
        chosenDistance[j] = kPprUnbounded;
        if (best == kPprNoChoice) continue;
        float d, f;
        vec3 mirrored, hit;
        takes(reflectors[best], points[j].xyz, eye, normals[j], above[j], kPprUnbounded, d, mirrored, hit, f);
        writeChosen(pixelOf(j), points[j].xyz, normals[j], eye, best, mirrored, hit, f, occluders);
    }
}

// Offers reflector i (data r) to the invocation's pixels in `live` (bit j: pixel j): each takes it
// where it reflects the pixel nearer than the pixel's choice so far.
void offer(ReflectorData r, uint i, uint live, vec4 points[kPixelsPerThread], vec3 normals[kPixelsPerThread],
           float above[kPixelsPerThread], vec3 eye) {
    for (uint j = 0u; j < kPixelsPerThread; ++j) {
        float d, f;
        vec3 mirrored, hit;
        if ((live & (1u << j)) == 0u || !takes(r, points[j].xyz, eye, normals[j], above[j], chosenDistance[j], d, mirrored, hit, f)) continue;
        chosen[j] = i;
        chosenDistance[j] = d;
    }
}

// projectTile where the tile's survivors lie in one cull plane (one orientation) and it built the
// plane grid. Each pixel mirrors itself once in the plane leader's plane and finds the cells around
// that hit: each candidate's own plane may lie up to kPprCullPlaneTolerance from the leader's, which
// moves its hit by at most that times (1 / the cosine of the ray with the normal, plus 2), so the
// cells within that margin hold every candidate whose rectangle can hold its own hit
// (ppr_common/plane_grid.h). The invocation then runs the exact per-reflector test over the
// candidates marked in any of its pixels' cells, in projection order, each read once for all its
// pixels; a candidate outside a pixel's own cells cannot hold its hit, so the test rejects it there
// and each pixel makes the choice it would make among its own cells' candidates.
void projectTileOnGrid(vec4 points[kPixelsPerThread], vec3 normals[kPixelsPerThread], float above[kPixelsPerThread], vec3 eye,
                       uint candidates, uint occluders) {
    uvec4 cellsOf[kPixelsPerThread];  // lo x, lo y, hi x, hi y
    uint live = 0u;  // bit j: pixel j has a point some candidate may reflect
    float eyeHeight = dot(eye - gridLeaderCenter, gridLeaderNormal);
    for (uint j = 0u; j < kPixelsPerThread; ++j) {
        cellsOf[j] = uvec4(1u, 1u, 0u, 0u);  // none
        if (points[j].w == 0.0) continue;
        vec3 p = points[j].xyz;
        float height = dot(p - gridLeaderCenter, gridLeaderNormal);
        float span = height + eyeHeight;  // the same for every candidate, up to rounding
        if (!(span > 0.5 * kPprAboveEpsilon)) continue;  // no candidate has the pixel above it and the eye in front
        vec3 mirrored = p - 2.0 * height * gridLeaderNormal;
        cellsOf[j] = pprPlaneGridCellsAround(grid, mix(eye, mirrored, eyeHeight / span),
                                             pprPlaneGridLookupMargin(p, eye, gridLeaderCenter, mirrored, span));
        live |= 1u << j;
    }
    if (live == 0u) return;
    for (uint w = 0u; w * 32u < candidates; ++w) {
        uint bits = 0u;
        for (uint j = 0u; j < kPixelsPerThread; ++j)
            for (uint y = cellsOf[j].y; y <= cellsOf[j].w; ++y)
                for (uint x = cellsOf[j].x; x <= cellsOf[j].z; ++x) bits |= gridWords[(x + y * kPprPlaneGridSize) * kPprPlaneGridWords + w];
        for (; bits != 0u; bits &= bits - 1u) {  // in projection order
            uint i = survivorAt(w * 32u + uint(findLSB(bits)));
            ReflectorData r = reflectors[i];
            if (!skipped(r, i)) offer(r, i, live, points, normals, above, eye);
        }
    }
    writeChoices(points, normals, above, eye, occluders);
}

// Projects this invocation's pixels of the tile into every reflector among the candidates that
// reflects them. Reflectors arrive sorted by orientation. Within one orientation only the shape
// nearest to a pixel (smallest plane distance) that reflects it is used, so each pixel is written at
// most once per orientation ("multiple parallel shapes"); different orientations each write their
// own. The candidates are the outer loop and the pixels the inner one, so each invocation reads a
// candidate once, not once per pixel (lavapipe: ppr.project 7.2 -> 5.7 ms, docs/performance.md).
void projectTile(vec4 points[kPixelsPerThread], uint candidates, uint occluders) {
    vec3 eye = frame.cameraPos.xyz;
    vec3 normals[kPixelsPerThread];
    float above[kPixelsPerThread];
    uint live = 0u;  // bit j: pixel j has a point (not sky, on screen)
    for (uint j = 0u; j < kPixelsPerThread; ++j) {
        chosen[j] = kPprNoChoice;
        chosenDistance[j] = kPprUnbounded;
        normals[j] = pc.facingOnly != 0u && points[j].w != 0.0 ? texelFetch(normalTex, pixelOf(j), 0).xyz : vec3(0.0);
        above[j] = kPprAboveEpsilon + kPprAboveEpsilonPerMetre * distance(eye, points[j].xyz);
        if (points[j].w != 0.0) live |= 1u << j;
    }
    if (gridPlane != kPprNoCullPlane) {
        projectTileOnGrid(points, normals, above, eye, candidates, occluders);
        return;
    }
    uint group = 0xFFFFFFFFu;
    for (uint k = 0u; k <= candidates; ++k) {
        uint i = k < candidates ? survivorAt(k) : 0u;
        uint g = k < candidates ? reflectors[i].orientationGroup : 0xFFFFFFFEu;
        if (g != group) {
            writeChoices(points, normals, above, eye, occluders);
            group = g;
        }
        if (k == candidates) break;
        ReflectorData r = reflectors[i];
        if (!skipped(r, i)) offer(r, i, live, points, normals, above, eye);
    }
}

void main() {
    uint lid = gl_LocalInvocationIndex;
    // Listed by the reach pass: the tile and its box, built and grown there.
    bool listed = pc.tileList != 0u;  // uniform
    PprReachedTile entry;
    if (listed) entry = reachTiles[gl_WorkGroupID.x];
    tile = listed ? pprUnpackTile(entry.lo.w) : gl_WorkGroupID.xy;
    if (lid == 0u) {
        boxLo = uvec3(0xFFFFFFFFu);
        boxHi = uvec3(0u);
        boxLeastDepth = floatBitsToUint(1.0);
        survivorCount = 0u;
        occluderCount = 0u;
        scatteredSubgroups = 0u;
        reachLoX = reachLoY = 0xFFFFu;
        reachHiX = reachHiY = 0u;
        survivorPlaneLo = kPprNoCullPlane;
        survivorPlaneHi = 0u;
    }
    if (pc.cullTiles != 0u) {
        // Only the words the lists can reach (their entries are or-ed into zeros): one entry at most
        // per reflector of the bounds pass's lists, survivors from the reflecting one, occluders from
        // the on-screen one. (Clearing all 2 × 512 words per tile cost 3 % of this pass on lavapipe.)
        for (uint w = lid; w < (visibleCounts.reflecting + 1u) / 2u; w += kThreads) survivorWords[w] = 0u;
        for (uint w = lid; w < (visibleCounts.onScreen + 1u) / 2u; w += kThreads) occluderWords[w] = 0u;
    }

    // Every pixel's world position, once, for the projection, and unless listed the tile's box as the
    // reach pass builds it (tile_box.h; it holds these positions once grown).
    vec4 points[kPixelsPerThread];  // xyz: world position; w: 1 with geometry, 0 for sky or off screen
    uvec3 lo = uvec3(0xFFFFFFFFu), hi = uvec3(0u);
    float leastDepth = 1.0;
    for (uint j = 0u; j < kPixelsPerThread; ++j) {
        points[j] = vec4(0.0);
        ivec2 pix = pixelOf(j);
        if (any(greaterThanEqual(pix, ivec2(frame.screenSize)))) continue;
        float depth = texelFetch(depthTex, pix, 0).r;
        if (depth <= 0.0) continue;  // sky: no position to mirror
        vec3 p = worldOfPixel(pix, depth);
        points[j] = vec4(p, 1.0);
        if (listed) continue;
        vec2 ndc = ndcOfPixelCentre(pix);
        uvec3 ordered = orderedFromFloat(pprBoxPoint(frame.invViewProj, pprBoxColumnTerm(frame.invViewProj, ndc.x),
                                                     pprBoxRowTerm(frame.invViewProj, ndc.y), depth));
        leastDepth = min(leastDepth, depth);
        lo = min(lo, ordered);
        hi = max(hi, ordered);
    }
    vec3 grownLo, grownHi;  // the box, grown
    if (listed) {
        lo = entry.lo.xyz;  // grown by the reach pass
        hi = entry.hi.xyz;
        grownLo = floatFromOrdered(lo);
        grownHi = floatFromOrdered(hi);
        barrier();  // the shared state above is initialised
    } else {
        lo = subgroupMin(lo);
        hi = subgroupMax(hi);
        leastDepth = subgroupMin(leastDepth);
        barrier();  // the shared state above is initialised
        if (subgroupElect() && lo.x <= hi.x) {
            atomicMin(boxLo.x, lo.x);
            atomicMin(boxLo.y, lo.y);
            atomicMin(boxLo.z, lo.z);
            atomicMax(boxHi.x, hi.x);
            atomicMax(boxHi.y, hi.y);
            atomicMax(boxHi.z, hi.z);
            atomicMin(boxLeastDepth, floatBitsToUint(leastDepth));
        }
        barrier();
        lo = boxLo;
        hi = boxHi;
        grownLo = floatFromOrdered(lo);
        grownHi = floatFromOrdered(hi);
        pprPadTileBox(frame.invViewProj, uintBitsToFloat(boxLeastDepth), grownLo, grownHi);
    }

    bool hasContent = lo.x <= hi.x;  // the same in every thread
    uint candidates = hasContent ? pc.reflectorCount : 0u, occluders = candidates;
    if (pc.cullTiles != 0u) {
        if (hasContent) cullReflectors(grownLo, grownHi);
        candidates = survivorCount;
        occluders = occluderCount;
    }
    if (lid == 0u) {
        tileSurvivors[tile.y * pc.tilesX + tile.x] = candidates;
        if (hasContent && !listed) atomicAdd(stats.tilesWithContent, 1u);  // else the reach pass counted them
        atomicAdd(stats.tilesProjected, 1u);
        if (candidates > 0u) atomicAdd(stats.tilesWithSurvivors, 1u);
        atomicAdd(stats.reflectorTilePairs, candidates);
        atomicAdd(stats.occluderTilePairs, occluders);
        atomicMax(stats.maxTileSurvivors, candidates);
        if (gridPlane != kPprNoCullPlane) atomicAdd(stats.tilesOnPlaneGrid, 1u);
    }
    projectTile(points, candidates, occluders);
}
