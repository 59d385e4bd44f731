#pragma once
// Minimal glTF 2.0 writer: one external .bin buffer, one bufferView per accessor, external PNG
// images, flat node list (all nodes are scene roots), LINEAR node animations. JSON uses
// insertion-ordered objects and numbers rounded to 1e-6 so the output is byte-stable and diff-friendly.
#include "mesh_builder.hpp"

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>
#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

namespace gen {

using Json = nlohmann::ordered_json;

// Rounds to 6 decimals (and folds −0 into 0) so JSON numbers print short and identically.
double num(double v);
Json vec(const glm::dvec3& v);

struct MaterialDesc {
    std::string name;
    glm::vec4 baseColor{1.0f};
    float metallic = 0.0f;
    float roughness = 1.0f;
    int baseColorTexture = -1, metallicRoughnessTexture = -1, normalTexture = -1;  // texture indices
    bool reflective = false;  // material extras {"ppr_reflective": true}
    bool transparent = false; // alphaMode "BLEND": glass (base colour = tint, alpha = tint strength)
};

struct NodeDesc {
    std::string name;
    glm::dvec3 translation{0.0};
    std::optional<glm::dquat> rotation;  // omitted when identity
    int mesh = -1, camera = -1;
    Json extras;  // null = none
};

// One animation with one LINEAR channel on one node.
struct AnimationDesc {
    std::string name;
    int node = -1;
    std::string path;           // "translation", "scale" (3 values per key) or "rotation" (4: x, y, z, w)
    std::vector<float> times;   // seconds, from 0, increasing
    std::vector<float> values;  // per key, in key order
};

class GltfWriter {
public:
    int addTexture(const std::string& uri);  // image + texture sharing one repeat/trilinear sampler
    int addMaterial(const MaterialDesc& m);
    int addMesh(const MeshData& mesh, int material);
    int addCamera(const std::string& name, double yfovRadians);
    // A 60° camera on a node with rotation R_y(−yaw)·R_x(pitch): local −Z then looks along
    // (sin yaw·cos pitch, sin pitch, −cos yaw·cos pitch), the --camera convention.
    int addCameraNode(const std::string& name, const glm::dvec3& position, double yawDeg, double pitchDeg);
    int addNode(const NodeDesc& node);
    int addAnimation(AnimationDesc animation);  // its data follows the meshes' in the .bin
    void setSceneExtras(Json extras) { sceneExtras_ = std::move(extras); }
    const MeshData& mesh(int index) const { return meshes_[static_cast<size_t>(index)]; }

    // Writes <dir>/<stem>.gltf and <dir>/<stem>.bin.
    void write(const std::string& dir, const std::string& stem) const;

private:
    std::vector<std::string> images_;
    std::vector<Json> materials_, cameras_, nodes_;
    std::vector<MeshData> meshes_;
    std::vector<int> meshMaterials_;
    std::vector<AnimationDesc> animations_;
    Json sceneExtras_;
};

}  // namespace gen
