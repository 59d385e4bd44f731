#include "fit/fit.hpp"

#include "cli/scene_source.hpp"
#include "scene/planar_regions.hpp"
#include "scene/stress_scene.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <regex>
#include <stdexcept>

namespace ppr::app {

std::vector<bool> selectFitMaterials(const scene::Scene& scene, const Options& o) {
    std::optional<std::regex> pattern;
    if (o.fitMaterials) {
        try {
            pattern.emplace(*o.fitMaterials, std::regex::ECMAScript);
        } catch (const std::regex_error& e) {
            throw std::runtime_error(printable("--materials " + *o.fitMaterials + ": not a regular expression (" + e.what() + ")"));
        }
    }
    const bool byFlag = !pattern && !o.fitMaxRoughness;
    std::vector<bool> selected(scene.materials.size(), false);
    size_t count = 0;
    for (size_t m = 0; m < scene.materials.size(); ++m) {
        const scene::Material& mat = scene.materials[m];
        bool take = byFlag ? mat.reflective : true;
        if (pattern) take = take && std::regex_search(mat.name, *pattern);
        if (o.fitMaxRoughness) take = take && mat.roughnessFactor <= *o.fitMaxRoughness;
        selected[m] = take;
        count += take;
    }
    if (count == 0) {
        std::string names;
        for (const scene::Material& mat : scene.materials) names += (names.empty() ? "" : ", ") + (mat.name.empty() ? "(unnamed)" : mat.name);
        throw std::runtime_error(printable(
            scene.sourcePath + ": no material selected (" +
            (byFlag ? std::string("none is marked reflective; give --materials REGEX or --max-roughness R") : "by --materials / --max-roughness") +
            "; materials: " + (names.empty() ? "none" : names) + ")"));
    }
    return selected;
}

std::string fitOutputPath(const Options& o) {
    if (o.outGiven) return o.out;
    const std::string scenePath = o.scene.empty() ? defaultScenePath() : o.scene;
    return (std::filesystem::path("out") / (std::filesystem::path(scenePath).stem().string() + ".reflectors.json")).string();
}

int runFit(const Options& o) {
    if (scene::parseStressSpec(o.scene)) throw std::runtime_error("--scene " + o.scene + ": ppr fit reads glTF scenes (the stress scene makes its own reflectors)");
    Options sceneOptions = o;
    sceneOptions.reflectors.clear();  // fit the surfaces, not whatever reflectors the scene comes with
    const scene::Scene scene = loadScene(sceneOptions);
    scene::PlanarRegionOptions ro;
    ro.materials = selectFitMaterials(scene, o);
    ro.minArea = o.fitMinArea;
    const scene::PlanarRegionResult result = scene::fitPlanarRegions(scene, ro);

    const std::string path = fitOutputPath(o);
    std::vector<scene::Reflector> reflectors;
    if (o.fitAppend && std::filesystem::exists(path)) reflectors = scene::loadReflectorFile(path);  // throws naming the file
    const size_t kept = reflectors.size();
    // An appended region whose name is taken gets the first free "<name>_<n>".
    auto freeName = [&](const std::string& name) {
        auto taken = [&](const std::string& n) {
            return std::any_of(reflectors.begin(), reflectors.end(), [&](const scene::Reflector& r) { return r.name == n; });
        };
        std::string candidate = name;
        for (int n = 2; taken(candidate); ++n) candidate = name + "_" + std::to_string(n);
        return candidate;
    };

    std::printf("%-24s %-24s %-6s %10s %10s %6s %10s %9s\n", "reflector", "material", "kind", "area m2", "rect m2", "fill", "off-plane", "triangles");
    for (const scene::FittedRegion& r : result.regions) {
        scene::Reflector reflector = r.reflector;
        reflector.name = freeName(reflector.name);
        const std::string& material = scene.materials[size_t(r.material)].name;
        std::printf("%-24s %-24s %-6s %10.3f %10.3f %6.3f %7.2f mm %9u\n", reflector.name.c_str(), material.c_str(),
                    reflector.kind == scene::ReflectorKind::Glass ? "glass" : "opaque", r.area, r.rectangleArea,
                    r.rectangleArea > 0.0 ? r.area / r.rectangleArea : 0.0, 1000.0 * r.maxPlaneDistance, r.triangles);
        reflectors.push_back(std::move(reflector));
    }
    std::printf("%zu reflectors; %u regions under --min-area %.3g m2 dropped, %u not flat within %.1f mm refused\n", reflectors.size() - kept,
                result.droppedSmall, double(ro.minArea), result.refused, 2000.0 * double(ro.planeTolerance));
    if (kept > 0) std::printf("%zu reflectors kept from %s (--append): %zu in all\n", kept, path.c_str(), reflectors.size());
    if (reflectors.size() > scene::kMaxReflectors)
        throw std::runtime_error(scene.sourcePath + ": " + std::to_string(reflectors.size()) + " regions fitted, more than a reflector file holds (" +
                                 std::to_string(scene::kMaxReflectors) + "); raise --min-area or narrow --materials");
    const std::filesystem::path parent = std::filesystem::path(path).parent_path();
    if (!parent.empty()) {
        std::error_code ec;
        std::filesystem::create_directories(parent, ec);
        if (ec) throw std::runtime_error("--out " + path + ": cannot create " + parent.string() + ": " + ec.message());
    }
    scene::saveReflectorFileAtomic(path, reflectors);
    std::printf("ppr: wrote %s (load it with --reflectors %s)\n", path.c_str(), path.c_str());
    return 0;
}

}  // namespace ppr::app
