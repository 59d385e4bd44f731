#pragma once
// The default PPR test scene: a walled courtyard with puddles, a mirror wall, a polished staircase
// and glass panels, so that one scene exercises horizontal, vertical and oblique reflectors,
// parallel reflectors at different heights and glass, each seen by a named camera.
#include <glm/glm.hpp>

#include <string>
#include <vector>

namespace gen {

struct ReflectorDesc {
    std::string name;
    glm::dvec3 center{0.0}, normal{0, 1, 0}, tangent{1, 0, 0};
    glm::dvec2 halfExtents{1.0};
    bool glass = false;
    double reflectance = 1.0;
};

// Writes default.gltf, default.bin, the PNG textures and default.reflectors.json into `dir`
// (which must exist).
void writeDefaultScene(const std::string& dir);

}  // namespace gen
