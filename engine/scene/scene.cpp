// Scene queries and the draw → reflector binding rule.
#include "scene/scene.hpp"

#include <cmath>

namespace ppr::scene {

const NamedCamera* Scene::findCamera(const std::string& name) const {
    for (const auto& c : cameras)
        if (c.name == name) return &c;
    return nullptr;
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
