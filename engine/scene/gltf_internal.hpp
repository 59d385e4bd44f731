#pragma once
// Internal to ppr_scene: what the glTF loader's files (gltf_*.cpp) share.
#include "scene/scene.hpp"

#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

#include <cstddef>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace ppr::scene::detail {

constexpr size_t kMaxElements = 50'000'000;  // vertices or indices per scene; beyond = absurd input

struct GltfFile {
    const tinygltf::Model& model;
    std::string name;  // the path as given: the prefix of every error message
};

// --- accessors (gltf_accessors.cpp): every range is checked before a byte is read.
// ScalarFloat: animation times; Rotation: animation quaternions (FLOAT or normalized integer VEC4).
enum class AccessorKind { Vec3Float, Vec4Float, TexCoord, Color, Index, ScalarFloat, Rotation };
struct AccessorView {
    const unsigned char* data = nullptr;  // into the glTF buffer, or into `owned`
    std::shared_ptr<const std::vector<unsigned char>> owned;  // a sparse accessor's elements, materialised
    size_t count = 0, stride = 0;
    int componentType = 0, components = 0;
    bool normalized = false;
};
AccessorView viewAccessor(const GltfFile& file, int accessor, AccessorKind kind, const std::string& what);
void readFloats(const AccessorView& view, size_t element, float* out);  // normalised ints → 0..1 / -1..1
uint32_t readIndex(const AccessorView& view, size_t element);

// --- meshes (gltf_meshes.cpp): one glTF primitive → Scene::meshes entry; -1 when skipped.
int loadPrimitive(const GltfFile& file, int mesh, int primitive, Scene& scene);

// --- extensions: what the loader implements (gltf_materials.cpp holds the list); a required one
// outside it is refused, an optional one warned about once and ignored.
bool isSupportedExtension(const std::string& name);

// --- materials and textures (gltf_materials.cpp): Scene::materials[i] is glTF material i.
void loadMaterials(const GltfFile& file, Scene& scene);

// --- extras (gltf_extras.cpp)
nlohmann::json toJson(const tinygltf::Value& value);
// The node's extras.ppr_reflector in world space, if any (validated; throws naming the node).
bool nodeReflector(const GltfFile& file, int node, const glm::mat4& world, Reflector& out);

std::string nodeLabel(const GltfFile& file, int node);  // "node 'Floor'" or "node 3"

// --- animations (gltf_animation.cpp): what the node walk recorded, for Scene::animation.
struct NodeTree {
    std::vector<int> parent;        // per glTF node: its parent, -1 for a root or a node outside the scene
    std::vector<glm::mat4> world;   // per glTF node: its rest world matrix (visited nodes only)
    std::vector<int> order;         // visited glTF nodes, parents before children
    std::vector<int> drawNode;      // per Scene::draws entry: the glTF node it came from
};
// Validates every channel (throws naming animation, channel and field) and fills scene.animation
// with the draws whose node or an ancestor is animated.
void loadAnimations(const GltfFile& file, const NodeTree& tree, Scene& scene);

}  // namespace ppr::scene::detail
