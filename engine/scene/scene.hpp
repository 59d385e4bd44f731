#pragma once
// CPU-side scene: what the glTF loader produces and the renderer uploads. Flattened: every mesh
// primitive instance becomes a DrawItem with its world matrix already resolved from the node hierarchy.
#include "scene/animation.hpp"
#include "scene/camera.hpp"
#include "scene/reflector.hpp"

#include <glm/glm.hpp>
#include <glm/gtc/type_precision.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace ppr::scene {

struct Vertex {
    glm::vec3 position;
    glm::vec3 normal;
    glm::vec4 tangent;  // xyz + handedness sign in w (glTF convention); generated when missing
    glm::vec2 uv0;
    glm::u16vec4 color{65535};  // COLOR_0 (linear RGBA, 16-bit unorm), multiplies the base colour; white when absent
};
static_assert(sizeof(Vertex) == 56);

struct TextureImage {
    std::string name;
    uint32_t width = 0, height = 0;
    std::vector<uint8_t> rgba8;  // always 4 channels
    bool srgb = false;           // base colour: true; normal / metallic-roughness: false
};

struct Material {
    std::string name;
    glm::vec4 baseColorFactor{1.0f};
    float metallicFactor = 1.0f;
    float roughnessFactor = 1.0f;
    float normalScale = 1.0f;
    int baseColorTexture = -1;          // index into Scene::textures
    int normalTexture = -1;
    int metallicRoughnessTexture = -1;  // glTF: G = roughness, B = metallic
    glm::vec3 emissiveFactor{0.0f};     // emitted radiance (linear), KHR_materials_emissive_strength applied
    int emissiveTexture = -1;           // sRGB, multiplies emissiveFactor
    // KHR_texture_transform (one per material: every texture uses it): uv' = (row0 · (uv, 1), row1 · (uv, 1)).
    glm::vec3 uvRow0{1.0f, 0.0f, 0.0f}, uvRow1{0.0f, 1.0f, 0.0f};
    bool reflective = false;            // material extras {"ppr_reflective": true}
    bool transparent = false;           // glTF alphaMode "BLEND": glass, drawn by the glass forward pass
                                        // (base colour = tint, alpha = how strongly it tints)
    bool masked = false;                // glTF alphaMode "MASK": cut out where base colour alpha < alphaCutoff
    float alphaCutoff = 0.5f;
};

struct Mesh {  // one glTF primitive (triangles)
    std::string name;
    uint32_t firstIndex = 0;   // into Scene::indices
    uint32_t indexCount = 0;
    int32_t vertexOffset = 0;  // into Scene::vertices
    int material = -1;         // -1 = default material
    glm::vec3 boundsMin{0.0f}, boundsMax{0.0f};  // object space
    bool vertexColors = false;  // COLOR_0 present: Vertex::color multiplies the base colour
};

struct DrawItem {
    uint32_t mesh = 0;
    glm::mat4 world{1.0f};
    std::string nodeName;
    int reflector = -1;  // index into Scene::reflectors whose rectangle this surface lies in, or -1
};

struct NamedCamera {
    std::string name;
    CameraPose pose;
};

struct Scene {
    std::string sourcePath;
    std::vector<Vertex> vertices;
    std::vector<uint32_t> indices;
    std::vector<Mesh> meshes;
    std::vector<Material> materials;
    std::vector<TextureImage> textures;
    std::vector<DrawItem> draws;
    std::vector<NamedCamera> cameras;
    std::vector<Reflector> reflectors;
    SceneAnimation animation;                    // the draws that move; DrawItem::world is their rest pose
    glm::vec3 boundsMin{0.0f}, boundsMax{0.0f};  // world space, all draws (at rest)

    const NamedCamera* findCamera(const std::string& name) const;
    // Whether an opaque material emits (a non-zero emissive factor; the texture only multiplies it).
    // Only then does the G-buffer need its emissive target: a glass pane emits in the glass pass.
    bool opaqueMaterialEmits() const;
};

struct LoadOptions {
    // Reflector file to use instead of the scene's own; empty = "<scene stem>.reflectors.json" beside
    // the scene if it exists, otherwise the glTF node extras.
    std::string reflectorFile;
};

// Loads a .gltf or .glb. Throws std::runtime_error with one line "<file>: <what> : <problem>" for any
// bad input (missing file or buffer, malformed JSON, out-of-range indices/accessors, NaN/inf
// positions, unsupported primitive mode...). Never crashes on malformed files.
Scene loadGltf(const std::string& path, const LoadOptions& options = {});

// Binds each draw to the reflector whose rectangle contains all of its (world-space) vertices on the
// plane (within `tolerance` metres); node extras / name matches take precedence. Called by loadGltf.
void bindDrawsToReflectors(Scene& scene, float tolerance = 0.01f);
// The same rules against another reflector list (the editor's, as it changes): per draw, the index
// in `reflectors` of the reflector it was bound to at load (matched by name), else the one named like
// its node, else (reflective materials) one whose rectangle holds its geometry; -1 for none.
std::vector<int> bindDraws(const Scene& scene, const std::vector<Reflector>& reflectors, float tolerance = 0.01f);

}  // namespace ppr::scene
