#include "cli/scene_source.hpp"

#include "scene/stress_scene.hpp"

#include <filesystem>
#include <optional>
#include <stdexcept>

namespace ppr::app {

std::string defaultScenePath() {
    // Next to the executable first (installed/copied builds), then the build tree.
    std::error_code ec;
    std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
    if (!ec) {
        std::filesystem::path beside = exe.parent_path().parent_path() / "content" / "default" / "default.gltf";
        if (std::filesystem::exists(beside)) return beside.string();
    }
    return PPR_DEFAULT_SCENE;
}

scene::Scene loadScene(const Options& o) {
    if (std::optional<uint32_t> tiles = scene::parseStressSpec(o.scene)) {
        scene::Scene s = scene::makeStressScene(*tiles);
        if (!o.reflectors.empty()) {
            // As for glTF: an explicit file replaces the scene's reflectors; tiles rebind by name
            // ("tile_<i>") or by lying inside a reflector rectangle.
            s.reflectors = scene::loadReflectorFile(o.reflectors);
            for (scene::DrawItem& d : s.draws) d.reflector = -1;
            scene::bindDrawsToReflectors(s);
        }
        return s;
    }
    scene::LoadOptions lo;
    lo.reflectorFile = o.reflectors;
    return scene::loadGltf(o.scene.empty() ? defaultScenePath() : o.scene, lo);
}

std::vector<ResolvedCamera> resolveCameras(const scene::Scene& s, const std::string& spec) {
    if (spec.empty()) {
        std::vector<ResolvedCamera> all;
        for (const scene::NamedCamera& c : s.cameras) all.push_back({c.name, c.pose});
        if (all.empty()) {
            // No camera in the file: look at the scene from outside its bounds.
            glm::vec3 center = (s.boundsMin + s.boundsMax) * 0.5f;
            float radius = std::max(glm::length(s.boundsMax - s.boundsMin) * 0.5f, 0.5f);
            scene::CameraPose p;
            p.position = center + glm::vec3(0.0f, radius * 0.6f, radius * 1.8f);
            scene::yawPitchFromDirection(glm::normalize(center - p.position), p.yawDeg, p.pitchDeg);
            all.push_back({"auto", p});
        }
        return all;
    }
    if (auto pose = scene::parseCameraSpec(spec)) return {{"custom", *pose}};
    if (const scene::NamedCamera* c = s.findCamera(spec)) return {{c->name, c->pose}};
    std::string known;
    for (const scene::NamedCamera& c : s.cameras) known += (known.empty() ? "" : ", ") + c.name;
    throw std::runtime_error(printable("--camera " + spec + ": no such camera in " + s.sourcePath + " (known: " +
                                       (known.empty() ? "none" : known) + "; or give x,y,z,yawDeg,pitchDeg[,fovYDeg])"));
}

std::string reflectorFilePath(const Options& o) {
    if (!o.reflectors.empty()) return o.reflectors;
    const std::string scenePath = o.scene.empty() ? defaultScenePath() : o.scene;
    if (scenePath.rfind("stress:", 0) == 0) return {};
    const std::filesystem::path p(scenePath);
    return (p.parent_path() / (p.stem().string() + ".reflectors.json")).string();
}

}  // namespace ppr::app
