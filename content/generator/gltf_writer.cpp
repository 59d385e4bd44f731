#include "gltf_writer.hpp"

#include <cmath>
#include <cstring>
#include <fstream>
#include <stdexcept>

namespace gen {

namespace {

constexpr int kFloat = 5126, kUnsignedInt = 5125;
constexpr int kArrayBuffer = 34962, kElementArrayBuffer = 34963;

// Appends raw little-endian data, keeping every view 4-byte aligned (all our components are 4 bytes).
size_t appendBytes(std::vector<uint8_t>& bin, const void* data, size_t bytes) {
    const size_t offset = bin.size();
    bin.resize(offset + bytes);
    std::memcpy(bin.data() + offset, data, bytes);
    return offset;
}

// Exact float → JSON number (min/max must equal the stored values bit for bit).
Json exact(float v) { return static_cast<double>(v) == 0.0 ? Json(0.0) : Json(static_cast<double>(v)); }

}  // namespace

double num(double v) {
    const double r = std::round(v * 1e6) / 1e6;
    return r == 0.0 ? 0.0 : r;
}

Json vec(const glm::dvec3& v) { return Json::array({num(v.x), num(v.y), num(v.z)}); }

int GltfWriter::addTexture(const std::string& uri) {
    images_.push_back(uri);
    return static_cast<int>(images_.size() - 1);
}

int GltfWriter::addMaterial(const MaterialDesc& m) {
    Json pbr;
    pbr["baseColorFactor"] = Json::array({num(m.baseColor.r), num(m.baseColor.g), num(m.baseColor.b), num(m.baseColor.a)});
    if (m.baseColorTexture >= 0) pbr["baseColorTexture"] = {{"index", m.baseColorTexture}};
    pbr["metallicFactor"] = num(m.metallic);
    pbr["roughnessFactor"] = num(m.roughness);
    if (m.metallicRoughnessTexture >= 0) pbr["metallicRoughnessTexture"] = {{"index", m.metallicRoughnessTexture}};
    Json j;
    j["name"] = m.name;
    j["pbrMetallicRoughness"] = pbr;
    if (m.normalTexture >= 0) j["normalTexture"] = {{"index", m.normalTexture}, {"scale", 1.0}};
    if (m.reflective) j["extras"] = {{"ppr_reflective", true}};
    if (m.transparent) j["alphaMode"] = "BLEND";
    materials_.push_back(j);
    return static_cast<int>(materials_.size() - 1);
}

int GltfWriter::addMesh(const MeshData& mesh, int material) {
    if (mesh.positions.empty() || mesh.indices.empty()) throw std::runtime_error("empty mesh " + mesh.name);
    meshes_.push_back(mesh);
    meshMaterials_.push_back(material);
    return static_cast<int>(meshes_.size() - 1);
}

int GltfWriter::addCameraNode(const std::string& name, const glm::dvec3& position, double yawDeg, double pitchDeg) {
    constexpr double kDeg = 3.14159265358979323846 / 180.0;
    NodeDesc n;
    n.name = name;
    n.camera = addCamera(name, 60.0 * kDeg);
    n.translation = position;
    n.rotation = glm::angleAxis(-yawDeg * kDeg, glm::dvec3(0, 1, 0)) * glm::angleAxis(pitchDeg * kDeg, glm::dvec3(1, 0, 0));
    return addNode(n);
}

int GltfWriter::addCamera(const std::string& name, double yfovRadians) {
    Json perspective;
    perspective["aspectRatio"] = num(16.0 / 9.0);
    perspective["yfov"] = num(yfovRadians);
    perspective["znear"] = 0.05;
    Json j;
    j["name"] = name;
    j["type"] = "perspective";
    j["perspective"] = perspective;
    cameras_.push_back(j);
    return static_cast<int>(cameras_.size() - 1);
}

int GltfWriter::addNode(const NodeDesc& n) {
    Json j;
    j["name"] = n.name;
    if (n.mesh >= 0) j["mesh"] = n.mesh;
    if (n.camera >= 0) j["camera"] = n.camera;
    if (n.rotation) {
        const glm::dquat q = glm::normalize(*n.rotation);
        j["rotation"] = Json::array({num(q.x), num(q.y), num(q.z), num(q.w)});
    }
    if (n.translation != glm::dvec3(0.0)) j["translation"] = vec(n.translation);
    if (!n.extras.is_null()) j["extras"] = n.extras;
    nodes_.push_back(j);
    return static_cast<int>(nodes_.size() - 1);
}

int GltfWriter::addAnimation(AnimationDesc a) {
    const size_t perKey = a.path == "rotation" ? 4 : 3;
    if (a.path != "translation" && a.path != "rotation" && a.path != "scale") throw std::logic_error("animation " + a.name + ": bad path");
    if (a.node < 0 || static_cast<size_t>(a.node) >= nodes_.size()) throw std::logic_error("animation " + a.name + ": bad node");
    if (a.times.empty() || a.values.size() != a.times.size() * perKey) throw std::logic_error("animation " + a.name + ": bad key count");
    for (size_t k = 1; k < a.times.size(); ++k)
        if (!(a.times[k] > a.times[k - 1])) throw std::logic_error("animation " + a.name + ": times not increasing");
    animations_.push_back(std::move(a));
    return static_cast<int>(animations_.size() - 1);
}

void GltfWriter::write(const std::string& dir, const std::string& stem) const {
    std::vector<uint8_t> bin;
    Json bufferViews = Json::array(), accessors = Json::array(), meshes = Json::array();

    auto addAccessor = [&](const void* data, size_t count, int components, int componentType, const char* type,
                           int target, Json minMax = nullptr) {
        const size_t bytes = count * static_cast<size_t>(components) * 4;
        const size_t offset = appendBytes(bin, data, bytes);
        Json view = {{"buffer", 0}, {"byteOffset", offset}, {"byteLength", bytes}};
        if (target != 0) view["target"] = target;  // animation data is neither vertices nor indices
        bufferViews.push_back(view);
        Json a;
        a["bufferView"] = bufferViews.size() - 1;
        a["componentType"] = componentType;
        a["count"] = count;
        a["type"] = type;
        if (!minMax.is_null()) {
            a["min"] = minMax[0];
            a["max"] = minMax[1];
        }
        accessors.push_back(a);
        return static_cast<int>(accessors.size() - 1);
    };

    for (size_t i = 0; i < meshes_.size(); ++i) {
        const MeshData& m = meshes_[i];
        glm::vec3 lo = m.positions[0], hi = m.positions[0];
        for (const glm::vec3& p : m.positions) {
            lo = glm::min(lo, p);
            hi = glm::max(hi, p);
        }
        const Json bounds = Json::array({Json::array({exact(lo.x), exact(lo.y), exact(lo.z)}),
                                         Json::array({exact(hi.x), exact(hi.y), exact(hi.z)})});
        const size_t n = m.positions.size();
        Json attributes;
        attributes["POSITION"] = addAccessor(m.positions.data(), n, 3, kFloat, "VEC3", kArrayBuffer, bounds);
        attributes["NORMAL"] = addAccessor(m.normals.data(), n, 3, kFloat, "VEC3", kArrayBuffer);
        attributes["TANGENT"] = addAccessor(m.tangents.data(), n, 4, kFloat, "VEC4", kArrayBuffer);
        attributes["TEXCOORD_0"] = addAccessor(m.uvs.data(), n, 2, kFloat, "VEC2", kArrayBuffer);
        const int indices = addAccessor(m.indices.data(), m.indices.size(), 1, kUnsignedInt, "SCALAR", kElementArrayBuffer);
        Json prim;
        prim["attributes"] = attributes;
        prim["indices"] = indices;
        prim["material"] = meshMaterials_[i];
        prim["mode"] = 4;  // TRIANGLES
        meshes.push_back({{"name", m.name}, {"primitives", Json::array({prim})}});
    }
    // After the meshes, so adding an animation leaves every mesh byte where it was.
    Json animations = Json::array();
    for (const AnimationDesc& a : animations_) {
        // glTF requires min/max on an animation's input.
        const Json bounds = Json::array({Json::array({exact(a.times.front())}), Json::array({exact(a.times.back())})});
        const int input = addAccessor(a.times.data(), a.times.size(), 1, kFloat, "SCALAR", 0, bounds);
        const bool rotation = a.path == "rotation";
        const int output = addAccessor(a.values.data(), a.times.size(), rotation ? 4 : 3, kFloat, rotation ? "VEC4" : "VEC3", 0);
        Json sampler = {{"input", input}, {"interpolation", "LINEAR"}, {"output", output}};
        Json channel = {{"sampler", 0}, {"target", {{"node", a.node}, {"path", a.path}}}};
        animations.push_back({{"name", a.name}, {"channels", Json::array({channel})}, {"samplers", Json::array({sampler})}});
    }

    Json gltf;
    gltf["asset"] = {{"version", "2.0"}, {"generator", "ppr_make_default_scene"}};
    gltf["scene"] = 0;
    Json sceneNodes = Json::array();
    for (size_t i = 0; i < nodes_.size(); ++i) sceneNodes.push_back(i);
    Json scene = {{"name", stem}, {"nodes", sceneNodes}};
    if (!sceneExtras_.is_null()) scene["extras"] = sceneExtras_;
    gltf["scenes"] = Json::array({scene});
    gltf["nodes"] = nodes_;
    gltf["cameras"] = cameras_;
    gltf["meshes"] = meshes;
    gltf["materials"] = materials_;
    if (!animations.empty()) gltf["animations"] = animations;
    Json textures = Json::array(), images = Json::array();
    for (size_t i = 0; i < images_.size(); ++i) {
        images.push_back({{"uri", images_[i]}, {"mimeType", "image/png"}});
        textures.push_back({{"sampler", 0}, {"source", i}});
    }
    gltf["textures"] = textures;
    gltf["images"] = images;
    // LINEAR_MIPMAP_LINEAR / LINEAR, REPEAT in both directions.
    gltf["samplers"] = Json::array({{{"magFilter", 9729}, {"minFilter", 9987}, {"wrapS", 10497}, {"wrapT", 10497}}});
    gltf["accessors"] = accessors;
    gltf["bufferViews"] = bufferViews;
    gltf["buffers"] = Json::array({{{"uri", stem + ".bin"}, {"byteLength", bin.size()}}});

    const std::string binPath = dir + "/" + stem + ".bin";
    std::ofstream b(binPath, std::ios::binary);
    b.write(reinterpret_cast<const char*>(bin.data()), static_cast<std::streamsize>(bin.size()));
    if (!b) throw std::runtime_error(binPath + ": cannot write");
    const std::string gltfPath = dir + "/" + stem + ".gltf";
    std::ofstream g(gltfPath, std::ios::binary);
    g << gltf.dump(1, '\t') << '\n';
    if (!g) throw std::runtime_error(gltfPath + ": cannot write");
}

}  // namespace gen
