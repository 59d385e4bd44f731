// The command line: parseCommandLine (app/cli/cli.cpp) with the declared settings behind --set
// (app/settings/settings.cpp), parseTechniqueVariant for --technique T@key=value,..., and what the
// parsed options feed next without a GPU: --camera through resolveCameras (parseCameraSpec's numeric
// form, engine/scene/camera_spec.cpp, or a camera name) and --scene stress:N (parseStressSpec).
// Input: argv words, one per line (argv[0] is "ppr"). Parsing touches no file; the scene the
// cameras resolve against is the built-in stress scene, made in memory once.
#include "fuzz_check.hpp"

#include "cli/cli.hpp"
#include "cli/scene_source.hpp"
#include "scene/stress_scene.hpp"
#include "settings/settings.hpp"

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

using namespace ppr;

namespace {

std::vector<std::string> words(const uint8_t* data, size_t size) {
    std::vector<std::string> out{"ppr"};
    std::string word;
    for (size_t i = 0; i < size; ++i) {
        if (data[i] == '\n') {
            out.push_back(word);
            word.clear();
        } else {
            word += char(data[i]);
        }
    }
    if (!word.empty() || (size > 0 && data[size - 1] != '\n')) out.push_back(word);
    return out;
}

// Every --set and --technique override that parsing accepted applies cleanly, and each setting's
// canonical text (what report.json records) reads back to itself.
void checkSettings(const app::Options& o) {
    app::Settings s;
    for (const std::string& kv : o.sets) s.apply(kv);
    for (const std::string& t : o.techniques) {
        app::Settings variant = s;
        for (const std::string& kv : app::parseTechniqueVariant(t).sets) variant.apply(kv);
    }
    for (const app::SettingDecl& d : app::settingDecls()) {
        const std::string text = s.get(d.key);
        s.set(d.key, text);
        fuzz::check(s.get(d.key) == text, "setting " + d.key + ": canonical text '" + text + "' does not read back");
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::vector<std::string> args = words(data, size);
    std::vector<const char*> argv;
    for (const std::string& a : args) argv.push_back(a.c_str());
    argv.push_back(nullptr);

    app::Options o;
    try {
        o = app::parseCommandLine(int(args.size()), argv.data());
    } catch (const std::runtime_error& e) {
        fuzz::checkOneLine(e);
        return 0;
    }
    fuzz::check(o.width >= app::kMinSize && o.width <= app::kMaxSize && o.height >= app::kMinSize && o.height <= app::kMaxSize,
                "--size accepted out of range");
    fuzz::check(o.frames <= app::kMaxFrames && o.warmup <= app::kMaxFrames, "--frames/--warmup accepted out of range");
    // Parsing accepted these, so applying them must not throw (an exception here reaches std::terminate).
    checkSettings(o);

    try {
        scene::parseStressSpec(o.scene);
    } catch (const std::runtime_error& e) {
        fuzz::checkOneLine(e);
    }
    static const scene::Scene stress = scene::makeStressScene(4);
    try {
        for (const app::ResolvedCamera& c : app::resolveCameras(stress, o.camera))
            fuzz::check(std::isfinite(c.pose.position.x) && std::isfinite(c.pose.position.y) && std::isfinite(c.pose.position.z) &&
                            std::isfinite(c.pose.yawDeg) && c.pose.pitchDeg >= -90.0f && c.pose.pitchDeg <= 90.0f &&
                            c.pose.fovYDeg > 1.0f && c.pose.fovYDeg < 179.0f,
                        "--camera " + o.camera + ": accepted a bad pose");
    } catch (const std::runtime_error& e) {
        fuzz::checkOneLine(e);
    }
    return 0;
}
