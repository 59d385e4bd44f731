#include "scale_scene.hpp"

#include "gltf_writer.hpp"
#include "mesh_builder.hpp"
#include "textures.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace gen {
namespace {

constexpr int kGrid = 33;               // 33 × 33 = 1089 spheres, each its own mesh and material
constexpr int kTextures = 512;
constexpr int kTextureSize = 16;
constexpr float kSpacing = 1.2f, kRadius = 0.45f;
constexpr float kFloorHalf = kGrid * kSpacing * 0.5f + 2.0f;

// A small tileable texture per index: a two-tone checker in a hue of its own, so every texture's
// bytes differ.
Image swatch(int index) {
    const float hue = float(index) / float(kTextures) * 6.0f;
    auto channel = [&](float offset) { return std::clamp(std::abs(std::fmod(hue + offset, 6.0f) - 3.0f) - 1.0f, 0.0f, 1.0f); };
    const glm::vec3 c(channel(0.0f), channel(4.0f), channel(2.0f));
    Image img;
    img.width = img.height = kTextureSize;
    img.rgb.resize(size_t(kTextureSize) * kTextureSize * 3);
    for (int y = 0; y < kTextureSize; ++y)
        for (int x = 0; x < kTextureSize; ++x) {
            const float shade = ((x / 4 + y / 4) % 2) ? 1.0f : 0.6f;
            for (int k = 0; k < 3; ++k)
                img.rgb[(size_t(y) * kTextureSize + x) * 3 + k] = uint8_t(std::lround(255.0f * (0.15f + 0.8f * c[k] * shade)));
        }
    return img;
}

}  // namespace

void writeScaleScene(const std::string& dir, int segments) {
    if (segments < 4 || segments > 256 || segments % 2) throw std::runtime_error("sphere segments must be even, 4..256");
    GltfWriter w;
    std::filesystem::create_directories(dir + "/textures");
    for (int t = 0; t < kTextures; ++t) {
        const std::string uri = "textures/swatch_" + std::to_string(t) + ".png";
        writePng(dir + "/" + uri, swatch(t));
        w.addTexture(uri);
    }

    MaterialDesc floorMaterial;
    floorMaterial.name = "floor_polished";
    floorMaterial.baseColor = glm::vec4(0.18f, 0.18f, 0.2f, 1.0f);
    floorMaterial.roughness = 0.05f;
    floorMaterial.reflective = true;
    MeshData floor;
    addQuad(floor, {-kFloorHalf, 0.0f, kFloorHalf}, {2.0f * kFloorHalf, 0.0f, 0.0f}, {0.0f, 0.0f, -2.0f * kFloorHalf}, 2.0f);
    floor.name = "floor";
    NodeDesc floorNode;
    floorNode.name = "floor";
    floorNode.mesh = w.addMesh(floor, w.addMaterial(floorMaterial));
    w.addNode(floorNode);

    for (int i = 0; i < kGrid * kGrid; ++i) {
        MaterialDesc m;
        m.name = "sphere_" + std::to_string(i);
        m.roughness = 0.3f + 0.6f * float(i % 7) / 6.0f;
        m.baseColorTexture = i % kTextures;
        MeshData sphere;
        addSphere(sphere, glm::vec3(0.0f), kRadius, segments, segments / 2, 0.5f);
        sphere.name = m.name;
        NodeDesc n;
        n.name = m.name;
        n.mesh = w.addMesh(sphere, w.addMaterial(m));
        n.translation = {(float(i % kGrid) - 0.5f * float(kGrid - 1)) * kSpacing, kRadius + 0.1f, (float(i / kGrid) - 0.5f * float(kGrid - 1)) * kSpacing};
        w.addNode(n);
    }
    w.addCameraNode("overview", {0.0, 9.0, 24.0}, 0.0, -24.0);
    w.addCameraNode("grazing", {3.0, 1.2, 21.5}, -8.0, -6.0);
    w.write(dir, "scale");

    const std::string path = dir + "/scale.reflectors.json";
    std::ofstream f(path, std::ios::binary);
    f << "{\"version\": 1, \"reflectors\": [{\"name\": \"floor\", \"center\": [0, 0, 0], \"normal\": [0, 1, 0], \"tangent\": [1, 0, 0], "
         "\"half_extents\": [" << num(kFloorHalf) << ", " << num(kFloorHalf) << "], \"kind\": \"opaque\", \"reflectance\": 0.8}]}\n";
    if (!f) throw std::runtime_error(path + ": cannot write");
}

}  // namespace gen
