// Reflector fitting: plane fit, convex hull + rotating calipers (minimum-area rectangle), planar
// region growing and the whole-scene automatic fit. Computations run in double precision.
#include "scene/reflector_fit.hpp"

#include "scene/vertex_weld.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

namespace ppr::scene {

namespace {

using glm::dvec2;
using glm::dvec3;

double cross2(const dvec2& o, const dvec2& a, const dvec2& b) {
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

// Andrew's monotone chain; counter-clockwise, no repeated or collinear points. Fewer than 3 points
// back means the input has no area.
std::vector<dvec2> convexHull(std::vector<dvec2> pts) {
    std::sort(pts.begin(), pts.end(), [](const dvec2& a, const dvec2& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
    pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
    if (pts.size() < 3) return pts;
    std::vector<dvec2> h(2 * pts.size());
    size_t k = 0;
    for (size_t i = 0; i < pts.size(); ++i) {  // lower hull
        while (k >= 2 && cross2(h[k - 2], h[k - 1], pts[i]) <= 0.0) --k;
        h[k++] = pts[i];
    }
    for (size_t i = pts.size() - 1, t = k + 1; i-- > 0;) {  // upper hull
        while (k >= t && cross2(h[k - 2], h[k - 1], pts[i]) <= 0.0) --k;
        h[k++] = pts[i];
    }
    h.resize(k - 1);  // the last point repeats the first
    return h;
}

struct Rect2 {
    dvec2 center{0.0};
    dvec2 axisU{1.0, 0.0}, axisV{0.0, 1.0};  // unit, axisV = perp(axisU)
    double halfU = 0.0, halfV = 0.0;
};

// Minimum-area enclosing rectangle of a convex CCW polygon (>= 3 points) by rotating calipers: for
// each hull edge, the extreme points along the edge (max and min) and away from it (max height)
// only ever move forward around the hull, so each pointer advances at most once round.
Rect2 minAreaRect(const std::vector<dvec2>& h) {
    const size_t m = h.size();
    auto next = [m](size_t i) { return (i + 1) % m; };
    auto edgeDir = [&](size_t i) { return glm::normalize(h[next(i)] - h[i]); };
    auto perp = [](const dvec2& e) { return dvec2(-e.y, e.x); };  // inward for a CCW hull

    // Pointers for edge 0 by a full scan.
    dvec2 e = edgeDir(0);
    size_t jMax = 0, kTop = 0, lMin = 0;
    for (size_t p = 1; p < m; ++p) {
        if (glm::dot(h[p], e) > glm::dot(h[jMax], e)) jMax = p;
        if (glm::dot(h[p], perp(e)) > glm::dot(h[kTop], perp(e))) kTop = p;
        if (glm::dot(h[p], e) < glm::dot(h[lMin], e)) lMin = p;
    }

    Rect2 best;
    double bestArea = std::numeric_limits<double>::infinity();
    for (size_t i = 0; i < m; ++i) {
        e = edgeDir(i);
        const dvec2 n = perp(e);
        // Advance (bounded: floating ties must never loop).
        for (size_t s = 0; s < m && glm::dot(h[next(jMax)], e) > glm::dot(h[jMax], e); ++s) jMax = next(jMax);
        for (size_t s = 0; s < m && glm::dot(h[next(kTop)], n) > glm::dot(h[kTop], n); ++s) kTop = next(kTop);
        for (size_t s = 0; s < m && glm::dot(h[next(lMin)], e) < glm::dot(h[lMin], e); ++s) lMin = next(lMin);
        const dvec2 o = h[i];
        const double lo = glm::dot(h[lMin] - o, e), hi = glm::dot(h[jMax] - o, e);
        const double top = glm::dot(h[kTop] - o, n);
        const double area = (hi - lo) * top;
        if (area < bestArea) {
            bestArea = area;
            best.center = o + e * (0.5 * (lo + hi)) + n * (0.5 * top);
            best.axisU = e;
            best.axisV = n;
            best.halfU = 0.5 * (hi - lo);
            best.halfV = 0.5 * top;
        }
    }
    return best;
}

// Sign convention for an axis: the largest-magnitude component positive (first on ties).
dvec3 canonicalSign(const dvec3& v) {
    int big = 0;
    for (int c = 1; c < 3; ++c)
        if (std::abs(v[c]) > std::abs(v[big]) + 1e-6) big = c;
    return v[big] < 0.0 ? -v : v;
}

// Lexicographic a > b on (x, y, z), components equal within 1e-6 counting as equal.
bool lexGreater(const dvec3& a, const dvec3& b) {
    for (int c = 0; c < 3; ++c)
        if (std::abs(a[c] - b[c]) > 1e-6) return a[c] > b[c];
    return false;
}

bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// Closest distance from p to triangle abc (Ericson, Real-Time Collision Detection 5.1.5).
double pointTriangleDistance(const dvec3& p, const dvec3& a, const dvec3& b, const dvec3& c) {
    const dvec3 ab = b - a, ac = c - a, ap = p - a;
    const double d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
    if (d1 <= 0.0 && d2 <= 0.0) return glm::length(p - a);
    const dvec3 bp = p - b;
    const double d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
    if (d3 >= 0.0 && d4 <= d3) return glm::length(p - b);
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return glm::length(p - (a + ab * (d1 / (d1 - d3))));
    const dvec3 cp = p - c;
    const double d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
    if (d6 >= 0.0 && d5 <= d6) return glm::length(p - c);
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return glm::length(p - (a + ac * (d2 / (d2 - d6))));
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0)
        return glm::length(p - (b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)))));
    const double denom = 1.0 / (va + vb + vc);
    return glm::length(p - (a + ab * (vb * denom) + ac * (vc * denom)));
}

}  // namespace

std::optional<Reflector> fitReflector(const std::vector<glm::vec3>& tris, float planeTolerance) {
    if (tris.empty() || tris.size() % 3 != 0) return std::nullopt;
    dvec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
    for (const glm::vec3& p : tris) {
        if (!finite(p)) return std::nullopt;
        lo = glm::min(lo, dvec3(p));
        hi = glm::max(hi, dvec3(p));
    }
    const double diag2 = glm::dot(hi - lo, hi - lo);

    // Area-weighted normals: twice-area vectors g per triangle.
    const size_t triCount = tris.size() / 3;
    std::vector<dvec3> g(triCount);
    size_t largest = 0;
    double total2 = 0.0;  // twice the total area
    for (size_t t = 0; t < triCount; ++t) {
        const dvec3 a(tris[3 * t]), b(tris[3 * t + 1]), c(tris[3 * t + 2]);
        g[t] = glm::cross(b - a, c - a);
        const double len = glm::length(g[t]);
        total2 += len;
        if (len > glm::length(g[largest])) largest = t;
    }
    if (!(0.5 * total2 > 1e-6 * diag2) || 0.5 * total2 <= 1e-12) return std::nullopt;
    const dvec3 ref = glm::normalize(g[largest]);
    dvec3 aligned(0.0), winding(0.0), centroid(0.0);
    for (size_t t = 0; t < triCount; ++t) {
        aligned += glm::dot(g[t], ref) >= 0.0 ? g[t] : -g[t];
        winding += g[t];
        centroid += glm::length(g[t]) * (dvec3(tris[3 * t]) + dvec3(tris[3 * t + 1]) + dvec3(tris[3 * t + 2])) / 3.0;
    }
    centroid /= total2;
    dvec3 n = glm::normalize(aligned);  // |aligned| >= |g[largest]| > 0
    if (glm::dot(winding, n) < -1e-9 * total2) n = -n;

    for (const glm::vec3& p : tris)
        if (std::abs(glm::dot(dvec3(p) - centroid, n)) > double(planeTolerance)) return std::nullopt;

    // In-plane basis and 2D projection.
    const dvec3 helper = std::abs(n.x) < 0.6 ? dvec3(1, 0, 0) : (std::abs(n.y) < 0.6 ? dvec3(0, 1, 0) : dvec3(0, 0, 1));
    const dvec3 e1 = glm::normalize(glm::cross(n, helper));
    const dvec3 e2 = glm::cross(n, e1);
    std::vector<dvec2> pts;
    pts.reserve(tris.size());
    for (const glm::vec3& p : tris) pts.emplace_back(glm::dot(dvec3(p) - centroid, e1), glm::dot(dvec3(p) - centroid, e2));
    const std::vector<dvec2> hull = convexHull(std::move(pts));
    if (hull.size() < 3) return std::nullopt;
    const Rect2 r = minAreaRect(hull);
    if (std::min(r.halfU, r.halfV) < double(kMinHalfExtent)) return std::nullopt;

    auto world = [&](const dvec2& v) { return e1 * v.x + e2 * v.y; };
    const dvec3 axisU = canonicalSign(world(r.axisU)), axisV = canonicalSign(world(r.axisV));
    const double longer = std::max(r.halfU, r.halfV);
    bool alongU;
    if (std::abs(r.halfU - r.halfV) <= 1e-6 * longer)
        alongU = !lexGreater(axisV, axisU);
    else
        alongU = r.halfU > r.halfV;

    Reflector out;
    out.center = glm::vec3(centroid + world(r.center));
    out.normal = glm::vec3(n);
    dvec3 tangent = alongU ? axisU : axisV;
    tangent = glm::normalize(tangent - n * glm::dot(tangent, n));
    out.tangent = glm::vec3(tangent);
    out.halfExtents = alongU ? glm::vec2(float(r.halfU), float(r.halfV)) : glm::vec2(float(r.halfV), float(r.halfU));
    out.kind = ReflectorKind::Opaque;
    out.reflectance = 1.0f;
    return out;
}

std::vector<glm::vec3> worldTriangles(const Scene& scene, const DrawItem& draw) {
    std::vector<glm::vec3> out;
    if (draw.mesh >= scene.meshes.size()) return out;
    const Mesh& mesh = scene.meshes[draw.mesh];
    if (size_t(mesh.firstIndex) + mesh.indexCount > scene.indices.size() || mesh.vertexOffset < 0) return out;
    const uint32_t count = mesh.indexCount - mesh.indexCount % 3;
    out.reserve(count);
    for (uint32_t i = 0; i < count; ++i) {
        const size_t v = size_t(mesh.vertexOffset) + scene.indices[size_t(mesh.firstIndex) + i];
        if (v >= scene.vertices.size()) return {};
        out.push_back(glm::vec3(draw.world * glm::vec4(scene.vertices[v].position, 1.0f)));
    }
    return out;
}

std::optional<Reflector> fitPlanarRegion(const Scene& scene, const glm::vec3& point, const glm::vec3& normal,
                                         float planeTolerance) {
    if (!finite(point) || !finite(normal) || glm::length(normal) < 1e-6f) return std::nullopt;
    const dvec3 n = glm::normalize(dvec3(normal)), q(point);

    // Candidate triangles: on the plane (within tolerance) and facing along n.
    std::vector<glm::vec3> cand;
    for (const DrawItem& draw : scene.draws) {
        const std::vector<glm::vec3> tris = worldTriangles(scene, draw);
        for (size_t t = 0; t + 2 < tris.size(); t += 3) {
            const dvec3 a(tris[t]), b(tris[t + 1]), c(tris[t + 2]);
            if (std::abs(glm::dot(a - q, n)) > planeTolerance || std::abs(glm::dot(b - q, n)) > planeTolerance ||
                std::abs(glm::dot(c - q, n)) > planeTolerance)
                continue;
            if (!(glm::dot(glm::cross(b - a, c - a), n) > 0.0)) continue;  // back-facing or degenerate
            cand.insert(cand.end(), {tris[t], tris[t + 1], tris[t + 2]});
        }
    }
    const size_t count = cand.size() / 3;
    if (count == 0) return std::nullopt;

    // Seed: the candidate nearest to the point.
    size_t seed = 0;
    double seedDist = std::numeric_limits<double>::infinity();
    for (size_t t = 0; t < count; ++t) {
        const double d = pointTriangleDistance(q, dvec3(cand[3 * t]), dvec3(cand[3 * t + 1]), dvec3(cand[3 * t + 2]));
        if (d < seedDist) {
            seedDist = d;
            seed = t;
        }
    }

    // Connectivity: candidates sharing a vertex position (welded) are one region.
    UnionFind uf(count);
    forEachWeldedPair(
        cand.size(), [&](uint32_t v) { return dvec3(cand[v]); }, kRegionWeldDistance, [&](uint32_t w, uint32_t v) { uf.unite(w / 3, v / 3); });

    std::vector<glm::vec3> region;
    const uint32_t root = uf.find(uint32_t(seed));
    for (uint32_t t = 0; t < count; ++t)
        if (uf.find(t) == root) region.insert(region.end(), {cand[3 * t], cand[3 * t + 1], cand[3 * t + 2]});
    return fitReflector(region, 2.0f * planeTolerance);
}

std::vector<Reflector> autoFitAll(const Scene& scene, float planeTolerance) {
    std::vector<Reflector> out;
    for (size_t i = 0; i < scene.draws.size(); ++i) {
        const DrawItem& draw = scene.draws[i];
        if (draw.mesh >= scene.meshes.size()) continue;
        const int mat = scene.meshes[draw.mesh].material;
        if (mat < 0 || size_t(mat) >= scene.materials.size() || !scene.materials[size_t(mat)].reflective) continue;
        std::optional<Reflector> r = fitReflector(worldTriangles(scene, draw), planeTolerance);
        if (!r) continue;  // curved (or degenerate): not a rectangle
        r->name = !draw.nodeName.empty()                       ? draw.nodeName
                  : !scene.meshes[draw.mesh].name.empty() ? scene.meshes[draw.mesh].name
                                                          : "draw_" + std::to_string(i);
        r->kind = scene.materials[size_t(mat)].transparent ? ReflectorKind::Glass : ReflectorKind::Opaque;
        out.push_back(std::move(*r));
    }
    return out;
}

}  // namespace ppr::scene
