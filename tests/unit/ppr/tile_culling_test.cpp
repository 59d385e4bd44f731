// Per-tile reflector culling (passes/ppr_common/tile_culling.h) against brute force: random cameras,
// tiles and reflector rectangles, with an oracle written here from the projection pass's per-pixel
// logic (ppr_project.comp: main's reflector loop, writeOffset, occludedByOtherReflector). The cull
// may keep too much, never too little: whenever a tile point is reflected into a reflector, the
// pixel it is written to must lie in both rectangles the cull compares.
#include "common/reflector_buffer.hpp"
#include "common/reflector_data.h"
#include "ppr_common/tile_culling.h"
#include "scene/camera.hpp"
#include "scene/reflector.hpp"
#include "scene/reflector_groups.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace {

using glm::uvec2;
using glm::vec2;
using glm::vec3;
using glm::vec4;
using ppr::gpu::ReflectorData;

constexpr int kTile = 16;  // kPprTileSize

struct Rng {
    std::mt19937 gen;
    explicit Rng(uint32_t seed) : gen(seed) {}
    float uni(float a, float b) { return std::uniform_real_distribution<float>(a, b)(gen); }
    float logUni(float a, float b) { return std::exp(uni(std::log(a), std::log(b))); }
    int integer(int a, int b) { return std::uniform_int_distribution<int>(a, b)(gen); }
    bool chance(float p) { return uni(0.0f, 1.0f) < p; }
    vec3 unit() {
        std::normal_distribution<float> nd;
        for (;;) {
            vec3 v(nd(gen), nd(gen), nd(gen));
            const float len = glm::length(v);
            if (len > 1e-3f) return v / len;
        }
    }
};

// ---------------------------------------------------------------------------------------------
// Camera: the project's own view and projection (reverse-Z, infinite far plane, Vulkan clip space).

struct View {
    ppr::scene::CameraPose pose;
    vec2 screen{1280.0f, 720.0f};
    glm::mat4 viewProj{1.0f}, invViewProj{1.0f};
    vec3 eye{0.0f}, forward{0.0f, 0.0f, -1.0f};
};

View makeView(const ppr::scene::CameraPose& pose, vec2 screen) {
    View v;
    v.pose = pose;
    v.screen = screen;
    v.viewProj = ppr::scene::projectionMatrix(pose.fovYDeg, screen.x / screen.y, ppr::scene::kNearPlane) * ppr::scene::viewMatrix(pose);
    v.invViewProj = glm::inverse(v.viewProj);
    v.eye = pose.position;
    v.forward = ppr::scene::viewDirection(pose.yawDeg, pose.pitchDeg);
    return v;
}

View randomView(Rng& rng) {
    static const vec2 kScreens[] = {{1280, 720}, {1280, 720}, {1920, 1080}, {333, 177}, {97, 61}, {17, 16}};
    ppr::scene::CameraPose pose;
    pose.position = vec3(rng.uni(-20, 20), rng.uni(-5, 15), rng.uni(-20, 20));
    pose.yawDeg = rng.uni(-180, 180);
    pose.pitchDeg = rng.uni(-85, 85);
    pose.fovYDeg = rng.uni(40, 90);
    return makeView(pose, kScreens[rng.integer(0, 5)]);
}

// The world position a pixel position (continuous, in pixels) at clip-space w (view distance along
// the axis) reconstructs to, the way worldFromDepth does it (reverse-Z depth = near / w).
vec3 unproject(const View& v, vec2 pixelPos, float w) {
    const vec2 ndc = pixelPos / v.screen * 2.0f - 1.0f;
    const vec4 p = v.invViewProj * vec4(ndc, ppr::scene::kNearPlane / w, 1.0f);
    return vec3(p) / p.w;
}

// writeOffset's target pixel for a world point; nullopt where it would not write.
std::optional<uvec2> writtenPixel(const View& v, vec3 world) {
    const vec4 clip = v.viewProj * vec4(world, 1.0f);
    if (!(clip.w > 0.0f)) return std::nullopt;
    const vec2 ndc = vec2(clip) / clip.w;
    if (!(std::abs(ndc.x) < 1.0f && std::abs(ndc.y) < 1.0f)) return std::nullopt;
    const vec2 target = (ndc * 0.5f + 0.5f) * v.screen;
    const uvec2 pixel(static_cast<uint32_t>(std::floor(target.x)), static_cast<uint32_t>(std::floor(target.y)));
    if (pixel.x >= v.screen.x || pixel.y >= v.screen.y) return std::nullopt;  // an image store out of range does nothing
    return pixel;
}

// ---------------------------------------------------------------------------------------------
// Reflector rectangles.

struct Rect {
    vec3 center{0.0f}, normal{0.0f, 1.0f, 0.0f}, tangent{1.0f, 0.0f, 0.0f};
    float hu = 1.0f, hv = 1.0f;
    vec3 bitangent() const { return glm::cross(normal, tangent); }
};

ReflectorData toGpu(const Rect& r) {
    ReflectorData d{};
    d.center = r.center;
    d.halfExtentU = r.hu;
    d.normal = r.normal;
    d.halfExtentV = r.hv;
    d.tangent = r.tangent;
    d.reflectance = 1.0f;
    d.bitangent = r.bitangent();
    return d;
}

vec3 tangentFor(Rng& rng, vec3 n) {
    for (;;) {
        const vec3 t = glm::cross(n, rng.unit());
        const float len = glm::length(t);
        if (len > 1e-2f) return t / len;
    }
}

bool insideRect(const Rect& r, vec3 p) {
    const vec3 l = p - r.center;
    return std::abs(glm::dot(l, r.tangent)) <= r.hu && std::abs(glm::dot(l, r.bitangent())) <= r.hv;
}

// The brute-force oracle: the pixel that point p is written to through reflector r (main's loop and
// writeOffset, with the smallest "above" threshold the shader uses, so it reflects at least as much).
std::optional<uvec2> reflectedPixel(const View& v, const Rect& r, vec3 p) {
    const float d = glm::dot(p - r.center, r.normal);
    if (!(d > 1e-3f)) return std::nullopt;
    const float eyeHeight = glm::dot(v.eye - r.center, r.normal);
    if (!(eyeHeight > 0.0f)) return std::nullopt;
    const vec3 mirrored = p - 2.0f * d * r.normal;
    const vec3 hit = glm::mix(v.eye, mirrored, eyeHeight / (eyeHeight + d));
    if (!insideRect(r, hit)) return std::nullopt;
    return writtenPixel(v, mirrored);
}

// What the cull decides for reflector r and a tile box, with the cull plane through planePoint
// (r's own centre, or a coplanar leader's).
struct CullVerdict {
    ReflectorData reflector;  // in cull plane 0 (the plane tables' case)
    ppr::gpu::PprReflectorBounds bounds;
    uvec2 tileRect, reflectorRect;
    vec3 hitLo, hitHi;  // the tile's hit region in the plane
    bool reflects;
    bool meetsHitRegion;
    // The verdict both shaders use (the projection's survivors, the reach pass's tiles).
    bool kept() const { return ppr::gpu::pprTileMayReachReflector(reflector, bounds, tileRect, hitLo, hitHi); }
};

// The three tests of ppr_project.comp's cullReflectors, as the bounds pass and the tile compute them.
CullVerdict cull(const View& v, const Rect& r, vec3 lo, vec3 hi, vec3 planePoint) {
    CullVerdict c;
    c.reflector = toGpu(r);
    c.reflector.cullPlane = 0u;
    c.tileRect = ppr::gpu::pprTileReflectedRect(lo, hi, r.normal, planePoint, v.viewProj, v.screen);
    const ppr::gpu::PprReflectorBounds b = ppr::gpu::pprReflectorBounds(toGpu(r), v.viewProj, v.eye, v.screen);
    c.bounds = b;
    c.reflectorRect = b.rect;
    c.reflects = b.reflects != 0u;
    ppr::gpu::pprTileHitRegion(lo, hi, r.normal, planePoint, v.eye, c.hitLo, c.hitHi);
    c.meetsHitRegion = ppr::gpu::pprRectangleMeetsBox(toGpu(r), c.hitLo, c.hitHi);
    return c;
}

std::string rectText(uvec2 r) {
    if (r.x == ppr::gpu::kPprEmptyRectLo && r.y == ppr::gpu::kPprEmptyRectHi) return "empty";
    std::ostringstream s;
    s << "x " << (r.x & 0xFFFFu) << ".." << (r.y & 0xFFFFu) << " y " << (r.x >> 16u) << ".." << (r.y >> 16u);
    return s.str();
}

std::string v3(vec3 p) {
    char buf[128];
    std::snprintf(buf, sizeof buf, "(%.9g, %.9g, %.9g)", p.x, p.y, p.z);
    return buf;
}

std::string describe(const View& v, const Rect& r) {
    std::ostringstream s;
    s << "camera pos " << v3(v.pose.position) << " yaw " << v.pose.yawDeg << " pitch " << v.pose.pitchDeg << " fov " << v.pose.fovYDeg
      << " screen " << v.screen.x << "x" << v.screen.y << "\n  reflector centre " << v3(r.center) << " normal " << v3(r.normal)
      << " tangent " << v3(r.tangent) << " half extents " << r.hu << " x " << r.hv
      << "\n  eyeHeight " << glm::dot(v.eye - r.center, r.normal);
    return s.str();
}

// ---------------------------------------------------------------------------------------------
// Random tiles and reflectors for test 1.

struct Tile {
    std::vector<vec3> points;
    vec3 lo{3.4e38f}, hi{-3.4e38f};
};

// A 16x16 screen tile (the last row/column may be partial) with 16–256 of its pixels at random
// depths: a smooth surface, a depth edge, or scattered depths.
Tile randomTile(Rng& rng, const View& v) {
    const int W = static_cast<int>(v.screen.x), H = static_cast<int>(v.screen.y);
    const int tx = kTile * rng.integer(0, (W + kTile - 1) / kTile - 1), ty = kTile * rng.integer(0, (H + kTile - 1) / kTile - 1);
    std::vector<glm::ivec2> pixels;
    for (int y = ty; y < std::min(ty + kTile, H); ++y)
        for (int x = tx; x < std::min(tx + kTile, W); ++x) pixels.push_back({x, y});
    std::shuffle(pixels.begin(), pixels.end(), rng.gen);
    pixels.resize(std::min<size_t>(pixels.size(), static_cast<size_t>(rng.integer(16, 256))));
    const float D = rng.logUni(0.06f, 150.0f);
    const int mode = rng.integer(0, 2);
    const float far = D * rng.uni(1.0f, 4.0f);
    // A smooth surface: depth varies linearly across the tile.
    const vec2 slope(rng.uni(-0.004f, 0.004f), rng.uni(-0.004f, 0.004f));
    Tile t;
    for (glm::ivec2 px : pixels) {
        float w = D;
        if (mode == 0) w = D * (1.0f + slope.x * static_cast<float>(px.x - tx) + slope.y * static_cast<float>(px.y - ty));
        if (mode == 1) w = rng.chance(0.5f) ? D : far;
        if (mode == 2) w = rng.logUni(D, 10.0f * D);
        w = std::max(w, ppr::scene::kNearPlane);  // depth <= 1
        const vec3 p = unproject(v, vec2(px) + 0.5f, w);
        t.points.push_back(p);
        t.lo = glm::min(t.lo, p);
        t.hi = glm::max(t.hi, p);
    }
    return t;
}

enum class Kind { Targeted, Straddling, AimedRandomNormal, Grazing, SeenFromBehind, NearPlane, Anywhere, Count };
const char* kKindNames[] = {"targeted", "straddling", "aimed", "grazing", "from-behind", "near-plane", "anywhere"};

Kind randomKind(Rng& rng) {
    const int x = rng.integer(0, 99);
    if (x < 30) return Kind::Targeted;
    if (x < 42) return Kind::Straddling;
    if (x < 55) return Kind::AimedRandomNormal;
    if (x < 60) return Kind::Grazing;
    if (x < 70) return Kind::SeenFromBehind;
    if (x < 80) return Kind::NearPlane;
    return Kind::Anywhere;
}

// Rectangle in the plane (n, planePoint) around the point where a tile point's reflection crosses
// it, shifted so that it may or may not contain that crossing.
Rect rectAround(Rng& rng, const View& v, vec3 n, vec3 planePoint, vec3 tilePoint) {
    Rect r;
    r.normal = n;
    r.tangent = tangentFor(rng, n);
    r.hu = rng.logUni(0.05f, 20.0f);
    r.hv = rng.chance(0.3f) ? r.hu : rng.logUni(0.05f, 20.0f);
    const float dE = glm::dot(v.eye - planePoint, n), dP = glm::dot(tilePoint - planePoint, n);
    vec3 at = planePoint;
    if (dE > 0.0f && dP > 0.0f) at = glm::mix(v.eye, tilePoint - 2.0f * dP * n, dE / (dE + dP));
    at -= glm::dot(at - planePoint, n) * n;
    r.center = at + r.tangent * (r.hu * rng.uni(-1.4f, 1.4f)) + r.bitangent() * (r.hv * rng.uni(-1.4f, 1.4f));
    return r;
}

Rect randomReflector(Rng& rng, const View& v, const Tile& tile, Kind kind) {
    const vec3 P = tile.points[rng.integer(0, static_cast<int>(tile.points.size()) - 1)];
    const vec3 boxPoint = tile.lo + (tile.hi - tile.lo) * vec3(rng.uni(0, 1), rng.uni(0, 1), rng.uni(0, 1));
    switch (kind) {
    case Kind::Targeted:
    case Kind::Straddling:
    case Kind::SeenFromBehind: {
        // The plane that mirrors P onto a random on-screen point M (the perpendicular bisector).
        vec3 M;
        do {
            M = unproject(v, vec2(rng.uni(0, v.screen.x), rng.uni(0, v.screen.y)), rng.logUni(0.06f, 200.0f));
        } while (glm::length(P - M) < 1e-3f);
        const vec3 n = glm::normalize(P - M);
        const vec3 planePoint = kind == Kind::Straddling ? boxPoint : (P + M) * 0.5f;
        Rect r = rectAround(rng, v, n, planePoint, P);
        if (kind == Kind::SeenFromBehind) {
            r.normal = -r.normal;  // bitangent flips with it: still a right-handed frame
        }
        return r;
    }
    case Kind::AimedRandomNormal: {
        const vec3 n = rng.unit();
        return rectAround(rng, v, n, P - rng.logUni(0.005f, 30.0f) * n, P);
    }
    case Kind::Grazing: {
        // The camera just above the plane (eyeHeight 1e-7 .. 1e-2 m).
        vec3 n = rng.unit();
        if (glm::dot(P - v.eye, n) < 0.0f) n = -n;
        return rectAround(rng, v, n, v.eye - rng.logUni(1e-7f, 1e-2f) * n, P);
    }
    case Kind::NearPlane: {
        Rect r;
        r.normal = rng.unit();
        r.tangent = tangentFor(rng, r.normal);
        r.hu = rng.logUni(0.3f, 20.0f);
        r.hv = rng.logUni(0.3f, 20.0f);
        r.center = v.eye + v.forward * rng.uni(-0.2f, 0.2f) + rng.unit() * rng.uni(0.0f, 0.3f);
        return r;
    }
    default: {
        Rect r;
        r.normal = rng.unit();
        r.tangent = tangentFor(rng, r.normal);
        r.hu = rng.logUni(0.05f, 20.0f);
        r.hv = rng.logUni(0.05f, 20.0f);
        r.center = v.eye + rng.unit() * rng.logUni(0.05f, 50.0f);
        return r;
    }
    }
}

// ---------------------------------------------------------------------------------------------

TEST(PprTileCulling, NeverCullsAReflectorThatReflectsAPixelOfTheTile) {
    Rng rng(20240611u);
    constexpr int kCases = 40000;
    int reflectedCases = 0, culledCases = 0, culledUnreflected = 0, unreflectedCases = 0, reflectedPoints = 0;
    int failures = 0, leaderFailures = 0;
    int crossingCameraPlane = 0, crossingReflecting = 0, fromBehind = 0, straddlingTiles = 0;
    int perKind[static_cast<int>(Kind::Count)][3] = {};  // cases, with a reflected point, culled
    std::vector<std::string> reports;
    for (int c = 0; c < kCases; ++c) {
        const View v = randomView(rng);
        const Tile tile = randomTile(rng, v);
        const Kind kind = randomKind(rng);
        const Rect r = randomReflector(rng, v, tile, kind);
        // A coplanar leader (cullPlanes: same normal, offset within 1e-5 m) somewhere else in the plane.
        const vec3 leaderPoint = r.center + r.tangent * rng.uni(-10.0f, 10.0f) + r.bitangent() * rng.uni(-10.0f, 10.0f) +
                                 r.normal * rng.uni(-0.9e-5f, 0.9e-5f);

        const CullVerdict verdict = cull(v, r, tile.lo, tile.hi, r.center);
        const uvec2 leaderTileRect = ppr::gpu::pprTileReflectedRect(tile.lo, tile.hi, r.normal, leaderPoint, v.viewProj, v.screen);
        vec3 leaderHitLo, leaderHitHi;
        ppr::gpu::pprTileHitRegion(tile.lo, tile.hi, r.normal, leaderPoint, v.eye, leaderHitLo, leaderHitHi);
        const bool leaderMeetsHitRegion = ppr::gpu::pprRectangleMeetsBox(toGpu(r), leaderHitLo, leaderHitHi);
        const int k = static_cast<int>(kind);
        ++perKind[k][0];
        // Coverage of the awkward geometry: rectangles crossing the camera plane (w = 0), seen from
        // behind, and tiles with points on both sides of the plane.
        {
            int behind = 0;
            for (int e = 0; e < 4; ++e) {
                const vec3 corner = r.center + r.tangent * (e & 1 ? r.hu : -r.hu) + r.bitangent() * (e & 2 ? r.hv : -r.hv);
                behind += (v.viewProj * vec4(corner, 1.0f)).w <= 0.0f ? 1 : 0;
            }
            if (behind > 0 && behind < 4) ++crossingCameraPlane;
            if (glm::dot(v.eye - r.center, r.normal) <= 0.0f) ++fromBehind;
            bool up = false, down = false;
            for (const vec3& p : tile.points) (glm::dot(p - r.center, r.normal) > 0.0f ? up : down) = true;
            if (up && down) ++straddlingTiles;
        }
        if (!verdict.kept()) {
            ++culledCases;
            ++perKind[k][2];
        }

        bool any = false, failed = false;
        for (const vec3& p : tile.points) {
            const std::optional<uvec2> pixel = reflectedPixel(v, r, p);
            if (!pixel) continue;
            any = true;
            ++reflectedPoints;
            const bool ok = verdict.kept() && ppr::gpu::pprRectContains(verdict.tileRect, *pixel) &&
                            ppr::gpu::pprRectContains(verdict.reflectorRect, *pixel);
            const bool leaderOk = ppr::gpu::pprRectContains(leaderTileRect, *pixel) && leaderMeetsHitRegion;
            if (!ok && !failed) {
                ++failures;
                failed = true;
                if (reports.size() < 8) {
                    // Minimised: the same reflector and this one point as the whole tile.
                    const CullVerdict single = cull(v, r, p, p, r.center);
                    std::ostringstream s;
                    s << "case " << c << " (" << kKindNames[k] << ", " << tile.points.size() << " points): " << describe(v, r)
                      << "\n  point " << v3(p) << " -> pixel " << pixel->x << "," << pixel->y << "\n  tile box " << v3(tile.lo) << " .. "
                      << v3(tile.hi) << "\n  tile rect " << rectText(verdict.tileRect) << ", reflector rect "
                      << rectText(verdict.reflectorRect) << ", reflects " << verdict.reflects << "\n  single-point tile rect "
                      << rectText(single.tileRect) << " (kept " << single.kept() << ", contains "
                      << ppr::gpu::pprRectContains(single.tileRect, *pixel) << ")";
                    reports.push_back(s.str());
                }
            }
            if (!leaderOk) ++leaderFailures;
        }
        if (any) {
            ++reflectedCases;
            {
                int behind = 0;
                for (int e = 0; e < 4; ++e) {
                    const vec3 corner = r.center + r.tangent * (e & 1 ? r.hu : -r.hu) + r.bitangent() * (e & 2 ? r.hv : -r.hv);
                    behind += (v.viewProj * vec4(corner, 1.0f)).w <= 0.0f ? 1 : 0;
                }
                if (behind > 0 && behind < 4) ++crossingReflecting;
            }
            ++perKind[k][1];
        } else {
            ++unreflectedCases;
            if (!verdict.kept()) ++culledUnreflected;
        }
    }
    std::printf("[tile culling] %d cases: %d (%.1f%%) with a reflected point (%d points in all); the cull rejected %d (%.1f%%) "
                "of all cases, %d of the %d (%.1f%%) without one\n",
                kCases, reflectedCases, 100.0 * reflectedCases / kCases, reflectedPoints, culledCases, 100.0 * culledCases / kCases,
                culledUnreflected, unreflectedCases, 100.0 * culledUnreflected / std::max(unreflectedCases, 1));
    std::printf("[tile culling] %d reflectors crossing the camera plane (%d of them reflecting a point), %d seen from behind, "
                "%d tiles straddling the plane\n",
                crossingCameraPlane, crossingReflecting, fromBehind, straddlingTiles);
    for (int k = 0; k < static_cast<int>(Kind::Count); ++k)
        std::printf("[tile culling]   %-11s %5d cases, %5d reflecting, %5d culled\n", kKindNames[k], perKind[k][0], perKind[k][1],
                    perKind[k][2]);
    std::printf("[tile culling] counterexamples: %d (own plane), %d reflected points outside a coplanar leader's tile rect\n", failures,
                leaderFailures);
    for (const std::string& s : reports) std::printf("%s\n", s.c_str());

    EXPECT_EQ(failures, 0) << "reflectors culled (or rects missing the written pixel) although a tile point is reflected";
    EXPECT_EQ(leaderFailures, 0) << "a coplanar leader's plane (cullPlanes, within 1e-5 m) gives a tile rect missing the pixel";
    // The test only proves something when many cases reflect, and only shows culling works when it culls.
    EXPECT_GT(reflectedCases, kCases / 10);
    EXPECT_GT(culledUnreflected, unreflectedCases / 4);
    for (int k = 0; k < static_cast<int>(Kind::Count); ++k) EXPECT_GT(perKind[k][0], kCases / 50) << kKindNames[k];
    EXPECT_GT(crossingReflecting, 100);
    EXPECT_GT(fromBehind, kCases / 10);
    EXPECT_GT(straddlingTiles, kCases / 20);
}

TEST(PprTileCulling, OccluderCandidatesHoldEveryCrossingReflector) {
    Rng rng(77031u);
    constexpr int kCases = 40000;
    int checked = 0, failures = 0, closeHits = 0;
    std::vector<std::string> reports;
    for (int c = 0; c < kCases; ++c) {
        const View v = randomView(rng);
        // The hit on some reflector: anywhere on screen, at 2 mm .. 300 m (hits may lie nearer than
        // the near plane when the camera is close to the reflecting plane).
        const float w = rng.chance(0.15f) ? rng.logUni(0.002f, 0.05f) : rng.logUni(0.05f, 300.0f);
        const vec3 hit = unproject(v, vec2(rng.uni(0, v.screen.x), rng.uni(0, v.screen.y)), w);
        const std::optional<uvec2> pixel = writtenPixel(v, hit);
        if (!pixel) continue;
        // Another rectangle crossing the segment eye -> hit at t.
        const int tk = rng.integer(0, 4);
        const float t = tk < 3 ? rng.uni(1e-4f, 1.0f - 1e-4f) : tk == 3 ? rng.logUni(1e-4f, 1e-2f) : 1.0f - rng.logUni(1e-4f, 1e-2f);
        const vec3 d = hit - v.eye;
        const vec3 X = v.eye + d * t;
        Rect j;
        j.normal = rng.unit();
        j.tangent = tangentFor(rng, j.normal);
        j.hu = rng.logUni(0.05f, 20.0f);
        j.hv = rng.logUni(0.05f, 20.0f);
        j.center = X + j.tangent * (j.hu * rng.uni(-1.0f, 1.0f)) + j.bitangent() * (j.hv * rng.uni(-1.0f, 1.0f));
        // occludedByOtherReflector's own test decides whether it crosses.
        const float denom = glm::dot(d, j.normal);
        if (std::abs(denom) < 1e-8f) continue;
        const float tj = glm::dot(j.center - v.eye, j.normal) / denom;
        if (!(tj > 1e-4f && tj < 1.0f - 1e-4f && insideRect(j, v.eye + d * tj))) continue;
        ++checked;
        if (w < 0.05f) ++closeHits;
        const uvec2 rect = ppr::gpu::pprReflectorScreenRect(toGpu(j), v.viewProj, v.screen);
        if (!ppr::gpu::pprRectContains(rect, *pixel)) {
            ++failures;
            if (reports.size() < 8) {
                const vec4 clipX = v.viewProj * vec4(v.eye + d * tj, 1.0f);
                std::ostringstream s;
                s << "case " << c << ": " << describe(v, j) << "\n  hit " << v3(hit) << " (w " << w << ") -> pixel " << pixel->x << ","
                  << pixel->y << "; crossing at t " << tj << " (clip w " << clipX.w << "); occluder rect " << rectText(rect);
                reports.push_back(s.str());
            }
        }
    }
    std::printf("[occluders] %d crossings checked (%d with the hit nearer than the near plane), %d counterexamples\n", checked, closeHits,
                failures);
    for (const std::string& s : reports) std::printf("%s\n", s.c_str());
    EXPECT_EQ(failures, 0);
    EXPECT_GT(checked, kCases / 4);
}

// Found by probing beyond the distribution above: an occluder whose plane passes within micrometres
// of the camera projects to a sliver, and where the segment crosses it at clip w below kPprCullMinW
// the written pixel falls outside its clipped screen rectangle. Here: a floor 0.4 µm below the eye,
// crossed at w = 0.8 µm by the segment to a hit 2 µm away. pprReflectorBounds gives such a plane
// (within kPprNearEyePlane of the eye) the whole screen.
TEST(PprTileCulling, OccluderPassingThroughTheEyeKeepsThePixel) {
    const View v = makeView(ppr::scene::CameraPose{}, {1280, 720});  // at the origin, looking down -Z, fov 60
    Rect j;
    j.center = vec3(0.0f, -4e-7f, -4.5f);  // z from +1 (behind the camera) to -10
    j.normal = vec3(0, 1, 0);
    j.tangent = vec3(1, 0, 0);
    j.hu = 1.0f;
    j.hv = 5.5f;
    const vec3 hit(0.0f, -1e-6f, -2e-6f);
    const std::optional<uvec2> pixel = writtenPixel(v, hit);
    ASSERT_TRUE(pixel.has_value());
    const vec3 d = hit - v.eye;
    const float t = glm::dot(j.center - v.eye, j.normal) / glm::dot(d, j.normal);
    ASSERT_TRUE(t > 1e-4f && t < 1.0f - 1e-4f && insideRect(j, v.eye + d * t)) << t;
    const uvec2 rect = ppr::gpu::pprReflectorBounds(toGpu(j), v.viewProj, v.eye, v.screen).rect;
    EXPECT_TRUE(ppr::gpu::pprRectContains(rect, *pixel))
        << "pixel " << pixel->x << "," << pixel->y << " (crossing at t " << t << ", clip w " << (v.viewProj * vec4(d * t, 1.0f)).w
        << "), occluder rect " << rectText(rect);
}

// ---------------------------------------------------------------------------------------------
// Rectangle packing.

struct Unpacked {
    uint32_t x0, y0, x1, y1;
};
Unpacked unpack(uvec2 r) { return {r.x & 0xFFFFu, r.x >> 16u, r.y & 0xFFFFu, r.y >> 16u}; }
bool isEmpty(uvec2 r) { return r.x == ppr::gpu::kPprEmptyRectLo && r.y == ppr::gpu::kPprEmptyRectHi; }

ppr::gpu::PprScreenBounds bounds(vec2 lo, vec2 hi) {
    ppr::gpu::PprScreenBounds b;
    b.lo = lo;
    b.hi = hi;
    return b;
}

// The per-reflector verdict's special cases: a reflector seen from behind keeps no tile; one beyond
// the plane tables is judged on its own screen rectangle, whatever the tile's mirrored rectangle.
TEST(PprTileCulling, VerdictDropsBackFacingAndJudgesUntabledOnTheirRectangle) {
    ReflectorData r{};
    r.cullPlane = 0u;
    const uvec2 onScreen{10u | (20u << 16u), 30u | (40u << 16u)};
    const uvec2 empty{ppr::gpu::kPprEmptyRectLo, ppr::gpu::kPprEmptyRectHi};
    const vec3 everywhereLo(-1e30f), everywhereHi(1e30f);
    ppr::gpu::PprReflectorBounds b{};
    b.rect = onScreen;
    b.reflects = 1u;
    EXPECT_TRUE(ppr::gpu::pprTileMayReachReflector(r, b, onScreen, everywhereLo, everywhereHi));
    EXPECT_FALSE(ppr::gpu::pprTileMayReachReflector(r, b, empty, everywhereLo, everywhereHi));
    EXPECT_FALSE(ppr::gpu::pprTileMayReachReflector(r, b, onScreen, vec3(1e29f), vec3(1e30f)));  // hit region misses it
    b.reflects = 0u;
    EXPECT_FALSE(ppr::gpu::pprTileMayReachReflector(r, b, onScreen, everywhereLo, everywhereHi));
    b.reflects = 1u;
    r.cullPlane = ppr::gpu::kPprNoCullPlane;
    EXPECT_TRUE(ppr::gpu::pprTileMayReachReflector(r, b, empty, vec3(1e29f), vec3(1e30f)));
    b.rect = empty;
    EXPECT_FALSE(ppr::gpu::pprTileMayReachReflector(r, b, onScreen, everywhereLo, everywhereHi));
}

// The verdict in every combination of its cases, against its definition written out here; and its
// screen-rectangle half, which the reach pass evaluates first to build the hit region only when
// needed: it never rules out a kept reflector, and once it passes, a tabled reflector's verdict is
// the hit-region test alone.
TEST(PprTileCulling, VerdictAndItsOnScreenHalfInEveryCase) {
    const uvec2 onScreen{10u | (20u << 16u), 30u | (40u << 16u)}, elsewhere{100u | (200u << 16u), 130u | (240u << 16u)};
    const uvec2 empty{ppr::gpu::kPprEmptyRectLo, ppr::gpu::kPprEmptyRectHi};
    const vec3 hitRegions[2][2] = {{vec3(-1e30f), vec3(1e30f)}, {vec3(1e29f), vec3(1e30f)}};  // meets the rectangle, misses it
    int cases = 0, kept = 0;
    for (uint32_t reflects : {0u, 1u})
        for (uint32_t plane : {0u, ppr::gpu::kPprNoCullPlane})
            for (uvec2 own : {onScreen, elsewhere, empty})
                for (uvec2 mirrored : {onScreen, elsewhere, empty})
                    for (int h = 0; h < 2; ++h) {
                        ReflectorData r{};
                        r.cullPlane = plane;
                        ppr::gpu::PprReflectorBounds b{};
                        b.rect = own;
                        b.reflects = reflects;
                        const bool tabled = plane != ppr::gpu::kPprNoCullPlane, meets = h == 0, ownOnScreen = own != empty;
                        const bool overlap = own != empty && own == mirrored;  // the three rectangles are disjoint or equal
                        const bool expected = reflects != 0u && (tabled ? overlap && meets : ownOnScreen);
                        const bool verdict = ppr::gpu::pprTileMayReachReflector(r, b, mirrored, hitRegions[h][0], hitRegions[h][1]);
                        const bool half = ppr::gpu::pprTileMayReachReflectorOnScreen(r, b, mirrored);
                        EXPECT_EQ(verdict, expected) << "case " << cases;
                        if (verdict) EXPECT_TRUE(half) << "case " << cases;
                        if (half && tabled) EXPECT_EQ(verdict, meets) << "case " << cases;
                        ++cases;
                        kept += verdict;
                    }
    EXPECT_EQ(cases, 72);
    EXPECT_EQ(kept, 2 + 12);  // tabled: mirrored on its own on-screen rectangle, hit region meeting it (2); untabled: own on screen, whatever the rest (2 × 3 × 2)
}

TEST(PprTileCulling, RectPackingEdgeCases) {
    using namespace ppr::gpu;
    const vec2 screens[] = {{1280, 720}, {333, 177}, {1, 1}, {4096, 2160}};
    Rng rng(5150u);
    for (vec2 screen : screens) {
        const uvec2 full = pprFullScreenRect(screen);
        const uvec2 empty = pprPackBounds(pprEmptyBounds(), screen);
        EXPECT_TRUE(isEmpty(empty));
        const float m = kPprCullMarginPx;
        // Bounds off screen (beyond the margin) on every side are empty and overlap nothing.
        const ppr::gpu::PprScreenBounds offScreen[] = {
            bounds({-50, 10}, {-m - 0.01f, 20}),                   // left
            bounds({screen.x + m + 0.01f, 10}, {screen.x + 90, 20}),  // right (lo - margin >= width)
            bounds({10, -80}, {20, -m - 0.5f}),                    // above
            bounds({10, screen.y + m}, {20, screen.y + 400}),         // below (lo - margin == height)
            bounds({-1e30f, -1e30f}, {-1e29f, -1e29f}),
            bounds({5, 5}, {-5, 30}),                                // inverted
        };
        for (const auto& b : offScreen) {
            const uvec2 r = pprPackBounds(b, screen);
            EXPECT_TRUE(isEmpty(r)) << screen.x << "x" << screen.y << " " << rectText(r);
            EXPECT_FALSE(pprRectsOverlap(r, full));
            EXPECT_FALSE(pprRectsOverlap(full, r));
            EXPECT_FALSE(pprRectsOverlap(r, r));
            EXPECT_FALSE(pprRectsOverlap(r, empty));
        }
        // Bounds just off screen but within the margin still give a (clamped) rectangle.
        const uvec2 edge = pprPackBounds(bounds({-30, 0}, {-m + 0.5f, 0}), screen);
        ASSERT_FALSE(isEmpty(edge));
        EXPECT_EQ(unpack(edge).x0, 0u);
        EXPECT_EQ(unpack(edge).x1, 0u);
        EXPECT_TRUE(pprRectContains(edge, uvec2(0, 0)));
        // Empty never overlaps empty; full screen covers its corners.
        EXPECT_FALSE(pprRectsOverlap(empty, empty));
        EXPECT_TRUE(pprRectContains(full, uvec2(0, 0)));
        EXPECT_TRUE(pprRectContains(full, uvec2(screen) - 1u));
        EXPECT_FALSE(pprRectContains(empty, uvec2(0, 0)));

        // Random bounds (on, partly on and off screen): packing clamps to the screen, full screen
        // overlaps every non-empty one, overlap is symmetric and agrees with a per-pixel intersection.
        std::vector<uvec2> rects;
        for (int i = 0; i < 400; ++i) {
            vec2 a(rng.uni(-0.3f, 1.3f) * screen.x, rng.uni(-0.3f, 1.3f) * screen.y);
            vec2 b = a + vec2(rng.logUni(0.01f, 1.0f) * screen.x, rng.logUni(0.01f, 1.0f) * screen.y) * (rng.chance(0.1f) ? -1.0f : 1.0f);
            const uvec2 r = pprPackBounds(bounds(a, b), screen);
            rects.push_back(r);
            if (isEmpty(r)) continue;
            const Unpacked u = unpack(r);
            EXPECT_LE(u.x0, u.x1);
            EXPECT_LE(u.y0, u.y1);
            EXPECT_LT(u.x1, static_cast<uint32_t>(screen.x));
            EXPECT_LT(u.y1, static_cast<uint32_t>(screen.y));
            EXPECT_TRUE(pprRectsOverlap(full, r));
            EXPECT_TRUE(pprRectsOverlap(r, full));
            EXPECT_TRUE(pprRectsOverlap(r, r));
            EXPECT_FALSE(pprRectsOverlap(r, empty));
            // Every pixel of the original bounds that is on screen is inside.
            const vec2 px = glm::clamp(glm::floor((a + b) * 0.5f), vec2(0.0f), screen - 1.0f);
            if (a.x <= b.x && a.y <= b.y) {
                EXPECT_TRUE(pprRectContains(r, uvec2(px)));
            }
        }
        rects.push_back(empty);
        rects.push_back(full);
        for (size_t i = 0; i < rects.size(); ++i) {
            for (size_t k = 0; k < rects.size(); ++k) {
                const bool ab = pprRectsOverlap(rects[i], rects[k]);
                ASSERT_EQ(ab, pprRectsOverlap(rects[k], rects[i])) << rectText(rects[i]) << " / " << rectText(rects[k]);
                bool brute = false;
                if (!isEmpty(rects[i]) && !isEmpty(rects[k])) {
                    const Unpacked a = unpack(rects[i]), b = unpack(rects[k]);
                    brute = std::max(a.x0, b.x0) <= std::min(a.x1, b.x1) && std::max(a.y0, b.y0) <= std::min(a.y1, b.y1);
                    if (brute) {
                        const uvec2 shared(std::max(a.x0, b.x0), std::max(a.y0, b.y0));
                        EXPECT_TRUE(pprRectContains(rects[i], shared) && pprRectContains(rects[k], shared));
                    }
                }
                ASSERT_EQ(ab, brute) << rectText(rects[i]) << " / " << rectText(rects[k]);
            }
        }
    }
}

// ---------------------------------------------------------------------------------------------

TEST(PprTileCulling, TileReflectedRectEmptyBelowPlaneAndFullScreenBehindCamera) {
    using namespace ppr::gpu;
    ppr::scene::CameraPose pose;  // at the origin, looking down -Z
    const View v = makeView(pose, {1280, 720});
    const uvec2 full = pprFullScreenRect(v.screen);

    // A floor at y = 0: boxes below it, or touching it from below, mirror nothing.
    EXPECT_TRUE(isEmpty(pprTileReflectedRect({-1, -3, -6}, {1, -0.5f, -4}, {0, 1, 0}, {0, 0, 0}, v.viewProj, v.screen)));
    EXPECT_TRUE(isEmpty(pprTileReflectedRect({-1, -3, -6}, {1, 0, -4}, {0, 1, 0}, {0, 0, 0}, v.viewProj, v.screen)));
    // ...while a box above it does, in the lower half of the screen (+Y is up, NDC y down).
    const uvec2 above = pprTileReflectedRect({-0.1f, 0.4f, -5.1f}, {0.1f, 0.6f, -4.9f}, {0, 1, 0}, {0, -1, 0}, v.viewProj, v.screen);
    ASSERT_FALSE(isEmpty(above));
    EXPECT_GT(unpack(above).y0, 360u);

    // A mirror behind the camera facing it (plane z = 1, normal -Z): points in front of the camera
    // mirror to behind it, which has no finite screen bounds.
    EXPECT_EQ(pprTileReflectedRect({-1, -1, -4}, {1, 1, -3}, {0, 0, -1}, {0, 0, 1}, v.viewProj, v.screen), full);
    // One corner's mirror behind the camera is enough: a wall at z = -0.5 facing +Z and a box from
    // z = -3 to -0.2; the corner at z = -0.2 (above the wall) mirrors to z = -0.8, in front, the one
    // at z = -3 (below it) to z = 2, behind the camera.
    EXPECT_EQ(pprTileReflectedRect({-1, -1, -3}, {1, 1, -0.2f}, {0, 0, 1}, {0, 0, -0.5f}, v.viewProj, v.screen), full);

    // Random: any box entirely below a random plane is empty; any box partly above with a mirrored
    // corner clearly behind the camera (checked independently) gives the full screen.
    Rng rng(9931u);
    int below = 0, behind = 0;
    for (int i = 0; i < 20000; ++i) {
        const View rv = randomView(rng);
        const vec3 n = rng.unit(), planePoint = rv.eye + rng.unit() * rng.logUni(0.05f, 30.0f);
        vec3 lo = rv.eye + rng.unit() * rng.logUni(0.05f, 30.0f);
        vec3 hi = lo + vec3(rng.logUni(1e-3f, 3.0f), rng.logUni(1e-3f, 3.0f), rng.logUni(1e-3f, 3.0f));
        const uvec2 fullR = pprFullScreenRect(rv.screen);
        float highest = -3.4e38f;
        float minW = 3.4e38f;
        for (int k = 0; k < 8; ++k) {
            const vec3 corner((k & 1) ? hi.x : lo.x, (k & 2) ? hi.y : lo.y, (k & 4) ? hi.z : lo.z);
            const float d = glm::dot(corner - planePoint, n);
            highest = std::max(highest, d);
            minW = std::min(minW, (rv.viewProj * vec4(corner - 2.0f * d * n, 1.0f)).w);
        }
        if (highest < -1e-3f) {
            ++below;
            EXPECT_TRUE(isEmpty(pprTileReflectedRect(lo, hi, n, planePoint, rv.viewProj, rv.screen)));
        } else if (highest > 1e-3f && minW < -1e-3f) {
            ++behind;
            EXPECT_EQ(pprTileReflectedRect(lo, hi, n, planePoint, rv.viewProj, rv.screen), fullR);
        }
        // Shifted entirely below the plane: empty.
        if (highest > -1e-3f) {
            const vec3 shift = n * (highest + rng.logUni(1e-3f, 5.0f));
            const vec3 lo2 = lo - shift, hi2 = hi - shift;
            EXPECT_TRUE(isEmpty(pprTileReflectedRect(glm::min(lo2, hi2), glm::max(lo2, hi2), n, planePoint, rv.viewProj, rv.screen)));
        }
    }
    EXPECT_GT(below, 1000);
    EXPECT_GT(behind, 1000);
}

// ---------------------------------------------------------------------------------------------
// ReflectorBuffer::cullPlanes: the plane each reflector's tile rectangle is computed for.

ppr::scene::Reflector reflector(vec3 center, vec3 normal) {
    ppr::scene::Reflector r;
    r.center = center;
    r.normal = normal;
    r.tangent = std::abs(normal.x) > 0.9f ? vec3(0, 0, 1) : glm::normalize(glm::cross(normal, vec3(1, 0, 0)));
    r.halfExtents = vec2(1.0f);
    return r;
}

bool samePlane(const ppr::scene::Reflector& a, const ppr::scene::Reflector& b) {
    return a.normal == b.normal && std::abs(glm::dot(b.center - a.center, a.normal)) <= 1e-5f;
}

void expectValidCullPlanes(const std::vector<ppr::scene::Reflector>& rs, const std::vector<uint32_t>& planes) {
    ASSERT_EQ(planes.size(), rs.size());
    for (uint32_t i = 0; i < rs.size(); ++i) {
        ASSERT_LE(planes[i], i) << i;
        EXPECT_EQ(planes[planes[i]], planes[i]) << i << ": its cull plane's reflector must be a leader";
        EXPECT_TRUE(samePlane(rs[planes[i]], rs[i])) << i << " -> " << planes[i];
    }
}

TEST(PprTileCulling, CullPlanesShareTheFirstCoplanarReflector) {
    using ppr::passes::ReflectorBuffer;
    const vec3 up(0, 1, 0), down(0, -1, 0), east(1, 0, 0);
    const std::vector<ppr::scene::Reflector> rs = {
        reflector({0, 0, 0}, up),          // 0: floor
        reflector({5, 0, 3}, up),          // 1: same floor → 0
        reflector({2, 0.001f, 0}, up),     // 2: 1 mm above (same plane group, another cull plane) → 2
        reflector({0, 0, 4}, down),        // 3: the floor's plane seen from below → 3
        reflector({-4, 0.001f, 7}, up),    // 4: coplanar with 2 → 2
        reflector({9, 5e-6f, -2}, up),     // 5: within 10 µm of the floor → 0
        reflector({3, 1, 0}, east),        // 6: a wall → 6
        reflector({1, 0, -8}, down),       // 7: coplanar with 3 → 3
        reflector({0, 2, 0}, up),          // 8: a shelf 2 m up → 8
    };
    const ppr::scene::ReflectorGroups groups = ppr::scene::groupReflectors(rs);
    const std::vector<uint32_t> planes = ReflectorBuffer::cullPlanes(rs, groups);
    EXPECT_EQ(planes, (std::vector<uint32_t>{0, 0, 2, 3, 2, 0, 6, 3, 8}));
    expectValidCullPlanes(rs, planes);
    // The packed data carries it.
    const std::vector<ReflectorData> packed = ReflectorBuffer::pack(rs, groups);
    const std::vector<uint32_t> leaders = ReflectorBuffer::cullPlaneLeaders(planes);
    for (size_t i = 0; i < rs.size(); ++i) EXPECT_EQ(leaders.at(packed[i].cullPlane), planes[i]);

    // Random sets: a few planes (some 0.5 mm / 2 mm apart, opposite normals), reflectors scattered
    // over them in random order; with `withTilted`, also a normal tilted by 0.1° that groups as
    // parallel to +Y (scene::kParallelCosine) without being equal to it.
    Rng rng(424242u);
    const vec3 tilted = glm::normalize(vec3(std::sin(glm::radians(0.1f)), 1.0f, 0.0f));
    const vec3 normals[] = {up, down, east, tilted};
    const float offsets[] = {0.0f, 5e-4f, 2e-3f, 0.7f};
    int missedSharing = 0, missedTrials = 0;
    for (int trial = 0; trial < 600; ++trial) {
        const bool withTilted = trial % 2 == 1;
        std::vector<ppr::scene::Reflector> set;
        std::vector<int> planeId;
        const int n = rng.integer(1, 40);
        for (int i = 0; i < n; ++i) {
            const int ni = rng.integer(0, withTilted ? 3 : 2), oi = rng.integer(0, 3);
            const vec3 normal = normals[ni];
            const vec3 t = std::abs(normal.x) > 0.9f ? vec3(0, 0, 1) : glm::normalize(glm::cross(normal, vec3(1, 0, 0)));
            const vec3 b = glm::cross(normal, t);
            set.push_back(reflector(normal * offsets[oi] + t * rng.uni(-10, 10) + b * rng.uni(-10, 10), normal));
            planeId.push_back(ni * 4 + oi);
        }
        const std::vector<uint32_t> p = ReflectorBuffer::cullPlanes(set, ppr::scene::groupReflectors(set));
        expectValidCullPlanes(set, p);
        bool missed = false;
        for (int i = 0; i < n; ++i) {
            // The first reflector in the same plane (itself when none came before).
            const uint32_t first = static_cast<uint32_t>(std::find(planeId.begin(), planeId.end(), planeId[i]) - planeId.begin());
            if (!withTilted) {
                ASSERT_EQ(p[i], first) << "trial " << trial << " reflector " << i;
            } else if (p[i] != first) {
                ++missedSharing;  // see CullPlanesShareAcrossPlaneGroupBoundaries
                missed = true;
            }
        }
        missedTrials += missed ? 1 : 0;
    }
    std::printf("[cull planes] sets with a 0.1 deg tilted normal: %d reflectors in %d of 300 sets got their own cull plane "
                "although an earlier reflector lies in exactly the same plane\n",
                missedSharing, missedTrials);
}

// Plane groups (scene::groupReflectors) are built from first-come representatives with tolerances,
// which is not transitive: two reflectors in exactly the same plane can land in different plane
// groups when a nearly parallel representative (here tilted by 0.1 deg) is within 1 mm of one of
// them but not of the other. cullPlanes searches leaders per orientation group, so they share one.
TEST(PprTileCulling, CullPlanesShareAcrossPlaneGroupBoundaries) {
    const vec3 up(0, 1, 0);
    const vec3 tilted = glm::normalize(vec3(std::sin(glm::radians(0.1f)), 1.0f, 0.0f));
    const vec3 inTiltedPlane = glm::normalize(glm::cross(tilted, vec3(0, 0, 1)));  // ≈ (1, -0.0017, 0)
    const std::vector<ppr::scene::Reflector> rs = {
        reflector({0, 0, 0}, up),                                                     // 0: the floor
        reflector(inTiltedPlane * -0.3f, tilted),  // 1: tilted plane, 0.5 mm off the floor's at x = -0.3 m: joins its group
        reflector(inTiltedPlane * -5.0f, tilted),  // 2: same tilted plane, 8.7 mm off at x = -5 m: a group of its own
    };
    const ppr::scene::ReflectorGroups groups = ppr::scene::groupReflectors(rs);
    std::printf("[cull planes] plane groups %u %u %u\n", groups.planeGroup[0], groups.planeGroup[1], groups.planeGroup[2]);
    ASSERT_TRUE(samePlane(rs[1], rs[2]));
    EXPECT_EQ(ppr::passes::ReflectorBuffer::cullPlanes(rs, groups), (std::vector<uint32_t>{0, 1, 1}));
}

}  // namespace

namespace {

// A summary of coplanar reflectors (PprCullChunk) must never rule out a tile for which
// pprTileMayReachReflector keeps one of them. Random coplanar runs of 1..maxMembers reflectors
// around a random tile, summarised as the bounds pass does (union of screen rectangles, union of
// pprRectangleBox grown by the slack); `cases` runs.
void expectSummaryKeepsEveryKeptReflector(uint32_t seed, uint32_t maxMembers, int cases) {
    Rng rng(seed);
    int runsWithAKept = 0, ruledOut = 0;
    for (int c = 0; c < cases; ++c) {
        const View v = randomView(rng);
        const Tile tile = randomTile(rng, v);
        const Rect first = randomReflector(rng, v, tile, rng.chance(0.5f) ? Kind::Targeted : Kind::AimedRandomNormal);
        const float spread = rng.logUni(0.5f, 8.0f);
        ppr::gpu::PprCullChunk chunk{};
        chunk.rect = uvec2(0xFFFFFFFFu, 0u);
        chunk.boxLo = vec3(3.4e38f);
        chunk.boxHi = vec3(-3.4e38f);
        chunk.cullPlane = 0u;
        uvec2 lo(0xFFFFu), hi(0u);
        bool anyKept = false, anyMember = false;
        CullVerdict plane{};
        const uint32_t members = maxMembers <= ppr::gpu::kPprCullChunk ? maxMembers : uint32_t(rng.integer(1, int(maxMembers)));
        for (uint32_t m = 0; m < members; ++m) {
            Rect r = first;
            if (m > 0) {  // a coplanar neighbour (cull planes allow 10 µm), turned in the plane
                r.tangent = tangentFor(rng, r.normal);
                r.hu = rng.logUni(0.05f, 5.0f);
                r.hv = rng.logUni(0.05f, 5.0f);
                r.center += (first.tangent * rng.uni(-1, 1) + first.bitangent() * rng.uni(-1, 1)) * spread * (first.hu + first.hv) +
                            r.normal * rng.uni(-1e-5f, 1e-5f);
            }
            const CullVerdict verdict = cull(v, r, tile.lo, tile.hi, first.center);  // the plane through the leader's centre
            if (m == 0) plane = verdict;
            if (!verdict.reflects || !ppr::gpu::pprRectsOverlap(verdict.reflectorRect, verdict.reflectorRect)) continue;  // not a candidate
            anyMember = true;
            anyKept = anyKept || verdict.kept();
            const uvec2 rect = verdict.reflectorRect;
            lo = glm::min(lo, uvec2(rect.x & 0xFFFFu, rect.x >> 16u));
            hi = glm::max(hi, uvec2(rect.y & 0xFFFFu, rect.y >> 16u));
            vec3 boxLo, boxHi;
            ppr::gpu::pprRectangleBox(verdict.reflector, boxLo, boxHi);
            chunk.boxLo = glm::min(chunk.boxLo, boxLo - vec3(ppr::gpu::kPprCullSlack));
            chunk.boxHi = glm::max(chunk.boxHi, boxHi + vec3(ppr::gpu::kPprCullSlack));
        }
        if (!anyMember) continue;
        chunk.rect = uvec2(lo.x | (lo.y << 16u), hi.x | (hi.y << 16u));
        const bool mayReach = ppr::gpu::pprTileMayReachChunk(chunk, plane.tileRect, plane.hitLo, plane.hitHi);
        runsWithAKept += anyKept;
        ruledOut += !mayReach;
        ASSERT_TRUE(mayReach || !anyKept) << "case " << c << ": the summary ruled out a run with a kept reflector\n  " << describe(v, first);
    }
    std::printf("runs of up to %u: with a kept reflector %d, ruled out %d\n", maxMembers, runsWithAKept, ruledOut);
    EXPECT_GT(runsWithAKept, cases / 20);
    EXPECT_GT(ruledOut, cases / 20) << "the summary should rule out runs far from the tile's reflection";
}

}  // namespace

// The bounds pass's chunk summaries: a tile skips a run of kPprCullChunk candidates when the
// summary rules it out.
TEST(PprTileCulling, ChunkSummaryNeverRulesOutAKeptReflector) { expectSummaryKeepsEveryKeptReflector(20261127u, ppr::gpu::kPprCullChunk, 20000); }

// The bounds pass's cull-plane bounds (PprCullPlaneBounds), which the reach pass tests as one summary
// per plane beyond kPprReachPerReflector reflectors: every candidate of the plane, up to the stress
// scene's 1 024.
TEST(PprTileCulling, CullPlaneBoundsNeverRuleOutAKeptReflector) { expectSummaryKeepsEveryKeptReflector(20261129u, 1024u, 4000); }
