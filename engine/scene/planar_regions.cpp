// Planar region extraction for `ppr fit`: weld vertices through a hash grid, unite neighbouring
// coplanar triangles of one material (union-find), fit each region. Double precision throughout.
#include "scene/planar_regions.hpp"

#include "scene/reflector_fit.hpp"
#include "scene/vertex_weld.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

namespace ppr::scene {
namespace {

using glm::dvec3;

struct Triangle {
    dvec3 v[3];
    dvec3 normal;  // unit
    double area = 0.0;
    int material = -1;
    uint32_t draw = 0;
};

bool coplanar(const Triangle& a, const Triangle& b, double tolerance) {
    for (const dvec3& p : b.v)
        if (std::abs(glm::dot(p - a.v[0], a.normal)) > tolerance) return false;
    for (const dvec3& p : a.v)
        if (std::abs(glm::dot(p - b.v[0], b.normal)) > tolerance) return false;
    return true;
}

std::vector<Triangle> selectedTriangles(const Scene& scene, const PlanarRegionOptions& o) {
    std::vector<Triangle> out;
    for (uint32_t d = 0; d < scene.draws.size(); ++d) {
        const DrawItem& draw = scene.draws[d];
        if (draw.mesh >= scene.meshes.size()) continue;
        const int material = scene.meshes[draw.mesh].material;
        if (material < 0 || size_t(material) >= o.materials.size() || !o.materials[size_t(material)]) continue;
        const std::vector<glm::vec3> tris = worldTriangles(scene, draw);
        for (size_t t = 0; t + 2 < tris.size(); t += 3) {
            Triangle tri;
            for (int k = 0; k < 3; ++k) tri.v[k] = dvec3(tris[t + size_t(k)]);
            const dvec3 g = glm::cross(tri.v[1] - tri.v[0], tri.v[2] - tri.v[0]);
            const double len = glm::length(g);
            if (!(len > 1e-12) || !std::isfinite(len)) continue;  // degenerate: no plane, no area
            tri.normal = g / len;
            tri.area = 0.5 * len;
            tri.material = material;
            tri.draw = d;
            out.push_back(tri);
        }
    }
    return out;
}

std::string regionName(const Scene& scene, const Triangle& t) {
    const DrawItem& draw = scene.draws[t.draw];
    if (!draw.nodeName.empty()) return draw.nodeName;
    if (!scene.meshes[draw.mesh].name.empty()) return scene.meshes[draw.mesh].name;
    if (!scene.materials[size_t(t.material)].name.empty()) return scene.materials[size_t(t.material)].name;
    return "region";
}

}  // namespace

PlanarRegionResult fitPlanarRegions(const Scene& scene, const PlanarRegionOptions& o) {
    const std::vector<Triangle> tris = selectedTriangles(scene, o);
    // Triangles sharing a (welded) vertex join when they have the same material and are coplanar.
    UnionFind uf(tris.size());
    forEachWeldedPair(
        tris.size() * 3, [&](uint32_t v) { return tris[v / 3].v[v % 3]; }, kRegionWeldDistance, [&](uint32_t w, uint32_t v) {
            const Triangle &a = tris[w / 3], &b = tris[v / 3];
            if (w / 3 != v / 3 && a.material == b.material && uf.find(w / 3) != uf.find(v / 3) && coplanar(a, b, o.planeTolerance))
                uf.unite(w / 3, v / 3);
        });

    std::map<uint32_t, std::vector<uint32_t>> regions;  // root -> triangles, in first-triangle order
    std::map<uint32_t, uint32_t> drawTriangles;         // draw -> its selected triangles
    for (uint32_t t = 0; t < tris.size(); ++t) {
        regions[uf.find(t)].push_back(t);
        ++drawTriangles[tris[t].draw];
    }

    PlanarRegionResult result;
    for (const auto& [root, members] : regions) {
        double area = 0.0;
        std::map<uint32_t, double> drawArea;
        std::map<uint32_t, uint32_t> drawCount;
        std::vector<glm::vec3> soup;
        soup.reserve(members.size() * 3);
        for (uint32_t t : members) {
            area += tris[t].area;
            drawArea[tris[t].draw] += tris[t].area;
            ++drawCount[tris[t].draw];
            for (const dvec3& p : tris[t].v) soup.push_back(glm::vec3(p));
        }
        if (area < double(o.minArea)) {
            ++result.droppedSmall;
            continue;
        }
        std::optional<Reflector> fit = fitReflector(soup, 2.0f * o.planeTolerance);
        if (!fit) {
            ++result.refused;
            continue;
        }
        const Triangle& first = tris[members.front()];
        const uint32_t largestDraw =
            std::max_element(drawArea.begin(), drawArea.end(), [](const auto& a, const auto& b) { return a.second < b.second; })->first;
        FittedRegion r;
        r.material = first.material;
        r.triangles = uint32_t(members.size());
        r.area = area;
        r.rectangleArea = 4.0 * double(fit->halfExtents.x) * double(fit->halfExtents.y);
        for (const glm::vec3& p : soup) r.maxPlaneDistance = std::max(r.maxPlaneDistance, double(std::abs(fit->planeDistance(p))));
        Triangle named = first;
        named.draw = largestDraw;
        fit->name = regionName(scene, named);
        r.wholeDraw = drawCount[largestDraw] == drawTriangles[largestDraw];
        fit->kind = scene.materials[size_t(first.material)].transparent ? ReflectorKind::Glass : ReflectorKind::Opaque;
        r.reflector = std::move(*fit);
        result.regions.push_back(std::move(r));
    }
    std::stable_sort(result.regions.begin(), result.regions.end(), [](const FittedRegion& a, const FittedRegion& b) { return a.area > b.area; });
    // Unique names in area order. A region that is its draw's whole surface keeps the draw's name, so
    // the loader binds that draw to it by name; a part of a draw ("slab_1" the top, "slab_2" the
    // underside) is numbered, so the draw is bound per pixel to whichever part it lies on.
    std::set<std::string> used;
    for (FittedRegion& r : result.regions) {
        const std::string base = r.reflector.name;
        std::string name = base;
        if (!r.wholeDraw || used.count(base))
            for (int n = 1; n == 1 || used.count(name); ++n) name = base + "_" + std::to_string(n);
        used.insert(name);
        r.reflector.name = name;
    }
    return result;
}

}  // namespace ppr::scene
