// Scene queries and the draw → reflector binding rule.
#include "scene/scene.hpp"

#include <cmath>

namespace ppr::scene {

const NamedCamera* Scene::findCamera(const std::string& name) const {
    for (const auto& c : cameras)
        if (c.name == name) return &c;
    return nullptr;
}

bool Scene::opaqueMaterialEmits() const {
    for (const Material& m : materials)
        if (!m.transparent && m.emissiveFactor != glm::vec3(0.0f)) return true;
    return false;
}

namespace {

// All of the draw's world-space vertices lie on r's plane and inside its rectangle (both ± tolerance).
bool liesOn(const Scene& scene, const DrawItem& draw, const Reflector& r, float tolerance) {
    const Mesh& mesh = scene.meshes[draw.mesh];
    if (mesh.indexCount == 0 || size_t(mesh.firstIndex) + mesh.indexCount > scene.indices.size()) return false;
    for (uint32_t i = 0; i < mesh.indexCount; ++i) {
        const size_t v = size_t(mesh.vertexOffset) + scene.indices[mesh.firstIndex + i];
        if (v >= scene.vertices.size()) return false;
        const glm::vec3 p = glm::vec3(draw.world * glm::vec4(scene.vertices[v].position, 1.0f));
        if (std::abs(r.planeDistance(p)) > tolerance || !r.containsProjected(p, tolerance)) return false;
    }
    return true;
}

bool reflectiveMaterial(const Scene& scene, const Mesh& mesh) {
    return mesh.material >= 0 && size_t(mesh.material) < scene.materials.size() &&
           scene.materials[size_t(mesh.material)].reflective;
}

}  // namespace

std::vector<int> bindDraws(const Scene& scene, const std::vector<Reflector>& reflectors, float tolerance) {
    auto named = [&](const std::string& name) {
        for (size_t r = 0; r < reflectors.size(); ++r)
            if (!name.empty() && reflectors[r].name == name) return static_cast<int>(r);
        return -1;
    };
    std::vector<int> binding(scene.draws.size(), -1);
    for (size_t i = 0; i < scene.draws.size(); ++i) {
        const DrawItem& draw = scene.draws[i];
        int r = -1;
        if (draw.reflector >= 0 && size_t(draw.reflector) < scene.reflectors.size()) r = named(scene.reflectors[size_t(draw.reflector)].name);
        if (r < 0) r = named(draw.nodeName);
        if (r < 0 && draw.mesh < scene.meshes.size() && reflectiveMaterial(scene, scene.meshes[draw.mesh]))
            for (size_t k = 0; k < reflectors.size() && r < 0; ++k)
                if (liesOn(scene, draw, reflectors[k], tolerance)) r = static_cast<int>(k);
        binding[i] = r;
    }
    return binding;
}

void bindDrawsToReflectors(Scene& scene, float tolerance) {
    const int count = static_cast<int>(scene.reflectors.size());
    for (DrawItem& draw : scene.draws) {
        if (draw.reflector >= 0 && draw.reflector < count) continue;  // bound by node extras (or earlier)
        draw.reflector = -1;
        if (draw.mesh >= scene.meshes.size()) continue;
        for (int r = 0; r < count && draw.reflector < 0; ++r)
            if (!draw.nodeName.empty() && scene.reflectors[size_t(r)].name == draw.nodeName) draw.reflector = r;
        if (draw.reflector >= 0 || !reflectiveMaterial(scene, scene.meshes[draw.mesh])) continue;
        for (int r = 0; r < count && draw.reflector < 0; ++r)
            if (liesOn(scene, draw, scene.reflectors[size_t(r)], tolerance)) draw.reflector = r;
    }
}

}  // namespace ppr::scene
