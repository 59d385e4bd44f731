// loadGltf: reads the file with tinygltf, walks the node tree of the chosen scene and flattens it
// into draws, cameras and reflectors. Per-primitive work is in gltf_meshes.cpp, the animation of the
// draws that move in gltf_animation.cpp.
#include "scene/errors.hpp"
#include "scene/gltf_internal.hpp"
#include "util/json_depth.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>

namespace ppr::scene {

using namespace detail;
namespace fs = std::filesystem;

namespace {

constexpr int kMaxNodeDepth = 1000;  // recursion guard; real scenes are a few dozen deep

// tinygltf's first line, capped: it can quote a whole base64 data URI.
std::string firstLine(const std::string& text) {
    std::string s = text.substr(0, text.find('\n'));
    if (s.size() > 200) s = s.substr(0, 200) + "...";
    return s.empty() ? "unknown tinygltf failure" : s;
}

// tinygltf parses its JSON recursively: refuse nesting that would exhaust the stack (the JSON chunk
// of a .glb, the whole text of a .gltf) before it runs.
void refuseDeepNesting(const std::string& path, bool binary) {
    std::ifstream f(path, std::ios::binary);
    std::string json;
    if (binary) {
        char header[20] = {};  // magic, version, length, then the first chunk's length and type
        f.read(header, sizeof header);
        uint32_t chunkLength = 0;
        std::memcpy(&chunkLength, header + 12, 4);
        if (!f || std::string(header + 16, 4) != "JSON") return;  // tinygltf names the problem
        // At most what the file holds: the header's claim is not trusted (fuzz_gltf: a 20-byte file
        // claiming a 4 GiB chunk made this allocate and zero 1 GiB per load).
        std::error_code ec;
        const uint64_t fileSize = fs::file_size(path, ec);
        json.resize(size_t(std::min<uint64_t>(chunkLength, (ec || fileSize < 20) ? 0 : fileSize - 20)));
        f.read(json.data(), static_cast<std::streamsize>(json.size()));
        json.resize(static_cast<size_t>(f.gcount()));
    } else {
        json.assign(std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>());
    }
    if (const size_t at = util::jsonNestingExceeded(json); at != std::string::npos)
        fail(path + ": JSON nested deeper than " + std::to_string(util::kMaxJsonNesting) + " levels at byte " + std::to_string(at + 1));
}

void loadModel(const std::string& path, tinygltf::Model& model) {
    std::error_code ec;
    const auto status = fs::status(path, ec);
    if (!fs::exists(status)) fail(path + ": no such file");
    if (!fs::is_regular_file(status)) fail(path + ": not a regular file");
    char magic[4] = {};
    std::ifstream(path, std::ios::binary).read(magic, 4);
    const bool binary = std::string(magic, 4) == "glTF";  // content decides, not the extension
    refuseDeepNesting(path, binary);

    tinygltf::TinyGLTF loader;
    std::string err, warn;
    bool ok = false;
    try {
        ok = binary ? loader.LoadBinaryFromFile(&model, &err, &warn, path)
                    : loader.LoadASCIIFromFile(&model, &err, &warn, path);
    } catch (const std::exception& e) {
        fail(path + ": " + e.what());
    }
    // tinygltf reports some schema errors (e.g. a material's texture without "index") yet returns true.
    if (!ok || !err.empty()) fail(path + ": " + firstLine(err));
    if (!warn.empty()) fail(path + ": " + firstLine(warn));  // e.g. an image file that failed to load
    // A required extension changes how data must be read (Draco, quantization...): ignoring one we do
    // not implement would draw a wrong picture, so refuse. An optional one only loses its refinement.
    for (const std::string& name : model.extensionsRequired)
        if (!isSupportedExtension(name)) fail(path + ": extensionsRequired: '" + name + "' is not supported");
    for (const std::string& name : model.extensionsUsed)
        if (!isSupportedExtension(name)) std::cerr << path << ": extensionsUsed: '" << name << "' is not supported; ignored\n";
}

// Vertex positions and node transforms are each finite, yet their product can overflow (fuzz_gltf:
// x = -1.73e38 under a scale of 2 gave an infinite scene bound): the mesh's box corners in world
// space must stay finite, and every vertex lies within them.
bool finiteInWorld(const Mesh& mesh, const glm::mat4& world) {
    for (int corner = 0; corner < 8; ++corner) {
        const glm::vec3 local((corner & 1) ? mesh.boundsMax.x : mesh.boundsMin.x, (corner & 2) ? mesh.boundsMax.y : mesh.boundsMin.y,
                              (corner & 4) ? mesh.boundsMax.z : mesh.boundsMin.z);
        const glm::vec3 p = glm::vec3(world * glm::vec4(local, 1.0f));
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) return false;
    }
    return true;
}

glm::mat4 localMatrix(const GltfFile& file, int index) {
    const tinygltf::Node& n = file.model.nodes[size_t(index)];
    auto bad = [&](const std::string& problem) { fail(file.name + ": " + nodeLabel(file, index) + ": " + problem); };
    auto check = [&](const std::vector<double>& v, size_t want, const char* field) {
        if (!v.empty() && v.size() != want) bad(std::string(field) + ": expected " + std::to_string(want) + " numbers");
        for (double d : v)
            if (!std::isfinite(d)) bad(std::string(field) + ": not finite");
    };
    check(n.matrix, 16, "matrix");
    check(n.translation, 3, "translation");
    check(n.rotation, 4, "rotation");
    check(n.scale, 3, "scale");
    if (!n.matrix.empty()) {
        glm::dmat4 m = glm::make_mat4(n.matrix.data());  // glTF and glm are both column-major
        return glm::mat4(m);
    }
    glm::mat4 t(1.0f), r(1.0f), s(1.0f);
    if (!n.translation.empty()) t = glm::translate(glm::mat4(1.0f), glm::vec3(n.translation[0], n.translation[1], n.translation[2]));
    if (!n.rotation.empty()) {
        glm::quat q(float(n.rotation[3]), float(n.rotation[0]), float(n.rotation[1]), float(n.rotation[2]));  // glTF: x,y,z,w
        const float len = glm::length(q);
        if (!(len > 1e-6f)) bad("rotation: zero quaternion");
        r = glm::mat4_cast(q / len);
    }
    if (!n.scale.empty()) s = glm::scale(glm::mat4(1.0f), glm::vec3(n.scale[0], n.scale[1], n.scale[2]));
    return t * r * s;
}

struct Traversal {
    const GltfFile& file;
    Scene& scene;
    bool reflectorsFromExtras;
    std::vector<char> state = std::vector<char>(file.model.nodes.size(), 0);  // 0 new, 1 on the path, 2 done
    std::map<std::pair<int, int>, int> primitiveMesh;                          // (mesh, primitive) → Scene::meshes or -1
    NodeTree tree{std::vector<int>(file.model.nodes.size(), -1), std::vector<glm::mat4>(file.model.nodes.size()), {}, {}};

    void visit(int index, int parentNode, const glm::mat4& parent, int depth, const std::string& from) {
        const auto& nodes = file.model.nodes;
        if (index < 0 || size_t(index) >= nodes.size())
            fail(file.name + ": " + from + ": node " + std::to_string(index) + " out of range (" + std::to_string(nodes.size()) + " nodes)");
        const std::string label = nodeLabel(file, index);
        if (state[size_t(index)] == 1) fail(file.name + ": " + label + ": node hierarchy contains a cycle");
        if (state[size_t(index)] == 2) fail(file.name + ": " + label + ": node has more than one parent (glTF nodes must form trees)");
        if (depth > kMaxNodeDepth) fail(file.name + ": " + label + ": node hierarchy deeper than " + std::to_string(kMaxNodeDepth));
        state[size_t(index)] = 1;

        const tinygltf::Node& node = nodes[size_t(index)];
        const glm::mat4 world = parent * localMatrix(file, index);
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r)
                if (!std::isfinite(world[c][r])) fail(file.name + ": " + label + ": world transform is not finite");
        tree.parent[size_t(index)] = parentNode;
        tree.world[size_t(index)] = world;
        tree.order.push_back(index);
        if (node.camera >= 0) addCamera(index, world);
        int reflector = -1;
        if (reflectorsFromExtras) reflector = addReflector(index, world);
        if (node.mesh >= 0) addDraws(index, world, reflector);
        for (int child : node.children) visit(child, index, world, depth + 1, label + " children");
        state[size_t(index)] = 2;
    }

    void addCamera(int index, const glm::mat4& world) {
        const tinygltf::Node& node = file.model.nodes[size_t(index)];
        const std::string label = file.name + ": " + nodeLabel(file, index);
        if (size_t(node.camera) >= file.model.cameras.size())
            fail(label + ": camera " + std::to_string(node.camera) + " out of range");
        const tinygltf::Camera& cam = file.model.cameras[size_t(node.camera)];
        if (cam.type != "perspective") {
            std::cerr << label << ": " << cam.type << " camera ignored (only perspective cameras are used)\n";
            return;
        }
        NamedCamera out;
        out.name = !node.name.empty() ? node.name : !cam.name.empty() ? cam.name : "camera" + std::to_string(node.camera);
        const double fov = glm::degrees(cam.perspective.yfov);
        if (!(fov > 1.0 && fov < 179.0)) fail(label + ": camera yfov: " + fmtNum(fov) + " degrees out of range (1, 179)");
        out.pose.fovYDeg = float(fov);
        out.pose.position = glm::vec3(world[3]);
        const glm::vec3 dir = glm::mat3(world) * glm::vec3(0, 0, -1);  // glTF cameras look down local -Z
        if (!(glm::length(dir) > 1e-8f)) fail(label + ": camera transform is degenerate (zero scale?)");
        yawPitchFromDirection(dir, out.pose.yawDeg, out.pose.pitchDeg);
        scene.cameras.push_back(std::move(out));
    }

    int addReflector(int index, const glm::mat4& world) {
        Reflector r;
        if (!nodeReflector(file, index, world, r)) return -1;
        if (scene.reflectors.size() >= kMaxReflectors)
            fail(file.name + ": " + nodeLabel(file, index) + " extras.ppr_reflector: more than " + std::to_string(kMaxReflectors) + " reflectors");
        for (const auto& existing : scene.reflectors)
            if (existing.name == r.name)
                fail(file.name + ": " + nodeLabel(file, index) + " extras.ppr_reflector.name: duplicate reflector name '" + r.name + "'");
        scene.reflectors.push_back(std::move(r));
        return int(scene.reflectors.size() - 1);
    }

    void addDraws(int index, const glm::mat4& world, int reflector) {
        const tinygltf::Node& node = file.model.nodes[size_t(index)];
        if (size_t(node.mesh) >= file.model.meshes.size())
            fail(file.name + ": " + nodeLabel(file, index) + ": mesh " + std::to_string(node.mesh) + " out of range (" +
                 std::to_string(file.model.meshes.size()) + " meshes)");
        const auto& prims = file.model.meshes[size_t(node.mesh)].primitives;
        for (int p = 0; p < int(prims.size()); ++p) {
            auto [it, fresh] = primitiveMesh.try_emplace({node.mesh, p}, -1);
            if (fresh) it->second = loadPrimitive(file, node.mesh, p, scene);  // shared by every instance
            if (it->second < 0) continue;
            const Mesh& mesh = scene.meshes[size_t(it->second)];
            if (!finiteInWorld(mesh, world))
                fail(file.name + ": " + nodeLabel(file, index) + ": mesh '" + mesh.name + "' leaves the float range in world space");
            DrawItem draw;
            draw.mesh = uint32_t(it->second);
            draw.world = world;
            draw.nodeName = node.name;
            draw.reflector = reflector;
            scene.draws.push_back(std::move(draw));
            tree.drawNode.push_back(index);
        }
    }
};

std::vector<int> rootNodes(const GltfFile& file) {
    const auto& m = file.model;
    if (!m.scenes.empty()) {
        const int s = m.defaultScene >= 0 ? m.defaultScene : 0;
        if (size_t(s) >= m.scenes.size())
            fail(file.name + ": scene " + std::to_string(s) + " out of range (" + std::to_string(m.scenes.size()) + " scenes)");
        return m.scenes[size_t(s)].nodes;
    }
    // No scenes: every node that is nobody's child is a root.
    std::vector<char> isChild(m.nodes.size(), 0);
    for (const auto& n : m.nodes)
        for (int c : n.children)
            if (c >= 0 && size_t(c) < m.nodes.size()) isChild[size_t(c)] = 1;
    std::vector<int> roots;
    for (size_t i = 0; i < m.nodes.size(); ++i)
        if (!isChild[i]) roots.push_back(int(i));
    return roots;
}

void computeBounds(Scene& scene) {
    bool any = false;
    for (const DrawItem& d : scene.draws) {
        const Mesh& mesh = scene.meshes[d.mesh];
        for (int corner = 0; corner < 8; ++corner) {
            const glm::vec3 local((corner & 1) ? mesh.boundsMax.x : mesh.boundsMin.x, (corner & 2) ? mesh.boundsMax.y : mesh.boundsMin.y,
                                  (corner & 4) ? mesh.boundsMax.z : mesh.boundsMin.z);
            const glm::vec3 p = glm::vec3(d.world * glm::vec4(local, 1.0f));
            scene.boundsMin = any ? glm::min(scene.boundsMin, p) : p;
            scene.boundsMax = any ? glm::max(scene.boundsMax, p) : p;
            any = true;
        }
    }
}

}  // namespace

Scene loadGltf(const std::string& path, const LoadOptions& options) {
    tinygltf::Model model;
    loadModel(path, model);
    const GltfFile file{model, path};

    Scene scene;
    scene.sourcePath = path;
    loadMaterials(file, scene);

    // Reflector source, first match wins: explicit file, "<stem>.reflectors.json" sidecar, node extras.
    const fs::path p(path);
    const fs::path sidecar = p.parent_path() / (p.stem().string() + ".reflectors.json");
    bool fromExtras = false;
    if (!options.reflectorFile.empty()) scene.reflectors = loadReflectorFile(options.reflectorFile);
    else if (std::error_code ec; fs::exists(sidecar, ec)) scene.reflectors = loadReflectorFile(sidecar.string());
    else fromExtras = true;

    Traversal walk{file, scene, fromExtras};
    for (int root : rootNodes(file)) walk.visit(root, -1, glm::mat4(1.0f), 0, "scene nodes");
    loadAnimations(file, walk.tree, scene);  // draws keep their rest pose; the animation only adds to it

    bindDrawsToReflectors(scene);
    computeBounds(scene);
    return scene;
}

}  // namespace ppr::scene
