// glTF scenes: loadGltf (engine/scene/gltf_*.cpp) on .gltf text and .glb containers alike (the
// loader sniffs the magic, as for users' files): the nesting pre-scan, tinygltf's parse, then the
// project's own validation and flattening of nodes, accessors, meshes, materials, textures, cameras
// and extras reflectors, and the draw-to-reflector binding. A scene that loads must be one the
// renderer can upload as is: every index, mesh, material, texture and reflector reference in range
// and every number finite.
//
// loadGltf takes a path, so each input is written to a private directory in /dev/shm (RAM) that
// holds nothing else: relative buffer/image URIs and the "<stem>.reflectors.json" sidecar lookup
// find nothing there. The directory is removed at exit (or by the next run, after a crash).
#include "fuzz_check.hpp"

#include "scene/scene.hpp"

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include <unistd.h>

using namespace ppr;
namespace fs = std::filesystem;

namespace {

fs::path g_dir;

// A crash, timeout or Ctrl-C ends the process without atexit, so each run's directory carries its
// PID and the next run removes those whose process is gone.
void removeStaleDirs(const fs::path& base) {
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(base, ec)) {
        const std::string name = e.path().filename().string();
        if (name.rfind("ppr-fuzz-gltf-", 0) != 0) continue;
        const std::string pid = name.substr(14);
        if (pid.empty() || pid.find_first_not_of("0123456789") != std::string::npos) continue;
        if (!fs::exists("/proc/" + pid)) fs::remove_all(e.path(), ec);
    }
}

const std::string& inputPath() {
    static const std::string path = [] {
        const fs::path base = fs::exists("/dev/shm") ? fs::path("/dev/shm") : fs::temp_directory_path();
        removeStaleDirs(base);
        g_dir = base / ("ppr-fuzz-gltf-" + std::to_string(::getpid()));
        std::error_code ec;
        fs::remove_all(g_dir, ec);
        if (!fs::create_directory(g_dir, ec)) fuzz::broken("cannot create " + g_dir.string());
        std::atexit([] {
            std::error_code ec;
            fs::remove_all(g_dir, ec);
        });
        return (g_dir / "fuzz.gltf").string();
    }();
    return path;
}

bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// What the renderer relies on when it poses an animated scene's moving draws each frame: every
// reference in range, parents before children, and evaluate() safe at any time.
void checkAnimation(const scene::Scene& s) {
    const scene::SceneAnimation& a = s.animation;
    fuzz::check(a.drawNode.size() == a.draws.size(), "animation: drawNode and draws differ in length");
    for (size_t i = 0; i < a.draws.size(); ++i) {
        fuzz::check(a.draws[i] < s.draws.size() && (i == 0 || a.draws[i] > a.draws[i - 1]), "animation: draws out of range or order");
        fuzz::check(a.drawNode[i] < a.nodes.size(), "animation: draw node out of range");
    }
    for (size_t n = 0; n < a.nodes.size(); ++n) fuzz::check(a.nodes[n].parent < int(n), "animation: node after its child");
    for (const scene::AnimationChannel& c : a.channels) {
        fuzz::check(c.node < a.nodes.size() && !c.times.empty(), "animation: channel node out of range or no keys");
        const size_t perKey = c.interpolation == scene::AnimationChannel::Interpolation::CubicSpline ? 3 : 1;
        fuzz::check(c.values.size() == c.times.size() * perKey, "animation: channel values do not match its keys");
        for (size_t k = 1; k < c.times.size(); ++k) fuzz::check(c.times[k] > c.times[k - 1], "animation: key times not increasing");
    }
    fuzz::check(std::isfinite(a.duration) && a.duration >= 0.0f, "animation: bad duration");
    std::vector<glm::mat4> worlds;
    for (double t : {0.0, 0.5 * a.duration, double(a.duration), 1e9, -3.0}) {
        a.evaluate(t, worlds);
        fuzz::check(worlds.size() == a.draws.size(), "animation: evaluate() gave the wrong number of matrices");
    }
}

// What the renderer relies on when it uploads a loaded scene.
void checkScene(const scene::Scene& s) {
    for (const scene::Mesh& m : s.meshes) {
        fuzz::check(m.indexCount > 0 && m.indexCount % 3 == 0, "mesh '" + m.name + "': index count not a positive multiple of 3");
        fuzz::check(size_t(m.firstIndex) + m.indexCount <= s.indices.size(), "mesh '" + m.name + "': indices out of range");
        fuzz::check(m.vertexOffset >= 0, "mesh '" + m.name + "': negative vertex offset");
        for (uint32_t i = 0; i < m.indexCount; ++i)
            fuzz::check(size_t(m.vertexOffset) + s.indices[m.firstIndex + i] < s.vertices.size(), "mesh '" + m.name + "': vertex out of range");
        fuzz::check(m.material >= -1 && m.material < int(s.materials.size()), "mesh '" + m.name + "': material out of range");
        fuzz::check(finite(m.boundsMin) && finite(m.boundsMax), "mesh '" + m.name + "': bounds not finite");
    }
    for (const scene::Vertex& v : s.vertices) {
        fuzz::check(finite(v.position) && finite(v.normal) && finite(glm::vec3(v.tangent)) && std::isfinite(v.tangent.w) &&
                        std::isfinite(v.uv0.x) && std::isfinite(v.uv0.y),
                    "vertex attribute not finite");
        fuzz::check(std::abs(glm::length(v.normal) - 1.0f) < 1e-3f, "normal not unit length");
    }
    for (const scene::Material& m : s.materials)
        for (int t : {m.baseColorTexture, m.normalTexture, m.metallicRoughnessTexture})
            fuzz::check(t >= -1 && t < int(s.textures.size()), "material '" + m.name + "': texture out of range");
    for (const scene::TextureImage& t : s.textures)
        fuzz::check(t.width > 0 && t.height > 0 && t.rgba8.size() == size_t(t.width) * t.height * 4, "texture '" + t.name + "': bad size");
    for (const scene::DrawItem& d : s.draws) {
        fuzz::check(d.mesh < s.meshes.size(), "draw of node '" + d.nodeName + "': mesh out of range");
        fuzz::check(d.reflector >= -1 && d.reflector < int(s.reflectors.size()), "draw of node '" + d.nodeName + "': reflector out of range");
        for (int c = 0; c < 4; ++c) fuzz::check(finite(glm::vec3(d.world[c])) && std::isfinite(d.world[c][3]), "draw world matrix not finite");
    }
    for (const scene::Reflector& r : s.reflectors)
        fuzz::check(scene::validateReflector(r).empty(), "reflector '" + r.name + "': " + scene::validateReflector(r));
    for (const scene::NamedCamera& c : s.cameras)
        fuzz::check(finite(c.pose.position) && std::isfinite(c.pose.yawDeg) && c.pose.pitchDeg >= -90.0f && c.pose.pitchDeg <= 90.0f &&
                        c.pose.fovYDeg > 1.0f && c.pose.fovYDeg < 179.0f,
                    "camera '" + c.name + "': bad pose");
    fuzz::check(finite(s.boundsMin) && finite(s.boundsMax), "scene bounds not finite");
    checkAnimation(s);
}

}  // namespace

// The loader's notes on skipped content (points, orthographic cameras) go to std::cerr: muted, since
// they would drown libFuzzer's own output. Sanitizer reports and broken invariants write to fd 2.
extern "C" int LLVMFuzzerInitialize(int*, char***) {
    std::cerr.rdbuf(nullptr);
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string& path = inputPath();
    {
        std::ofstream out(path, std::ios::binary | std::ios::trunc);
        out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
        if (!out) fuzz::broken("cannot write " + path);
    }
    try {
        checkScene(scene::loadGltf(path));
    } catch (const std::runtime_error& e) {
        fuzz::checkOneLine(e);
    }
    return 0;
}
