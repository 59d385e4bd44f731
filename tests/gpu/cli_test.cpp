// The `ppr` executable per the interface contract: capture of every named camera with validation,
// report.json fields, and one-line errors for bad input.
#include "gpu_test_util.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstring>

namespace ppr::test {
namespace {

TEST(Cli, CaptureEveryNamedCameraWithValidation) {
    auto dir = tempDir("cli-all");
    RunResult r = runPpr("capture --validation --size 320x180 --frames 2 --out " + dir.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    scene::Scene s = scene::loadGltf(PPR_DEFAULT_SCENE_FILE);
    ASSERT_GE(s.cameras.size(), 5u);
    for (const scene::NamedCamera& c : s.cameras) {
        auto report = readJson(dir / c.name / "report.json");
        EXPECT_EQ(report["validation_errors"], 0) << c.name;
        EXPECT_EQ(report["validation"], true);
        for (const char* key : {"device", "api_version", "size", "technique", "settings", "frames", "passes", "total_gpu_ms", "images"})
            EXPECT_TRUE(report.contains(key)) << key;
        EXPECT_EQ(report["size"][0], 320);
        EXPECT_EQ(report["images"]["final"], "final.png");
        EXPECT_TRUE(report["passes"].contains("lighting"));
        util::Rgba8Image img = util::readPng((dir / c.name / "final.png").string());
        EXPECT_GT(lumaStdDev(img), 10.0) << c.name;
    }
    std::filesystem::remove_all(dir);
}

// `ppr fit` on the default scene: every authored reflector and the steel post's flat top, written
// as a file that renders (with validation) nearly as the authored one does on a camera that sees the
// puddles, and bad selections refused with one line.
TEST(Cli, FitWritesAReflectorFileThatRenders) {
    auto dir = tempDir("cli-fit");
    RunResult fit = runPpr("fit --out " + (dir / "fit.reflectors.json").string());
    ASSERT_EQ(fit.exitCode, 0) << fit.output;
    EXPECT_NE(fit.output.find("puddle_large"), std::string::npos) << fit.output;
    EXPECT_NE(fit.output.find("20 reflectors"), std::string::npos) << fit.output;
    std::vector<scene::Reflector> fitted = scene::loadReflectorFile((dir / "fit.reflectors.json").string());
    EXPECT_EQ(fitted.size(), 20u);
    // The fit knows shapes, not the artist's reflectance: take those from the authored file.
    const std::filesystem::path authoredFile = std::filesystem::path(PPR_DEFAULT_SCENE_FILE).parent_path() / "default.reflectors.json";
    for (const scene::Reflector& a : scene::loadReflectorFile(authoredFile.string()))
        for (scene::Reflector& f : fitted)
            if (f.name == a.name) f.reflectance = a.reflectance;
    scene::saveReflectorFileAtomic((dir / "fit.reflectors.json").string(), fitted);
    for (const char* which : {"fit", "authored"}) {
        const std::string reflectors = std::string(which) == "fit" ? " --reflectors " + (dir / "fit.reflectors.json").string() : "";
        RunResult r = runPpr("capture --validation --camera puddles --size 160x90 --frames 1" + reflectors + " --out " + (dir / which).string());
        ASSERT_EQ(r.exitCode, 0) << r.output;
    }
    const util::Rgba8Image a = util::readPng((dir / "fit" / "final.png").string());
    const util::Rgba8Image b = util::readPng((dir / "authored" / "final.png").string());
    ASSERT_EQ(a.pixels.size(), b.pixels.size());
    size_t differing = 0;
    for (size_t i = 0; i < a.pixels.size(); i += 4) differing += std::memcmp(&a.pixels[i], &b.pixels[i], 3) != 0;
    EXPECT_LT(differing, a.pixels.size() / 4 / 100) << "more than 1 % of the pixels changed with the fitted reflectors";

    // --append keeps what the file holds and adds after it, renaming what collides: the mirrors
    // fitted again over the 20 come back as "mirror_2" and "mirror_wavy_2".
    RunResult append = runPpr("fit --materials '^mirror' --append --out " + (dir / "fit.reflectors.json").string());
    ASSERT_EQ(append.exitCode, 0) << append.output;
    EXPECT_NE(append.output.find("20 reflectors kept from"), std::string::npos) << append.output;
    const std::vector<scene::Reflector> appended = scene::loadReflectorFile((dir / "fit.reflectors.json").string());
    ASSERT_GT(appended.size(), fitted.size());
    for (size_t i = 0; i < fitted.size(); ++i) EXPECT_EQ(appended[i].name, fitted[i].name);
    std::vector<std::string> added;
    for (size_t i = fitted.size(); i < appended.size(); ++i) added.push_back(appended[i].name);
    EXPECT_NE(std::find(added.begin(), added.end(), "mirror_2"), added.end()) << append.output;
    EXPECT_NE(std::find(added.begin(), added.end(), "mirror_wavy_2"), added.end()) << append.output;

    RunResult none = runPpr("fit --materials nothing_matches --out " + (dir / "none.json").string());
    EXPECT_EQ(none.exitCode, 2);
    EXPECT_NE(none.output.find("no material selected"), std::string::npos) << none.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "none.json"));
    std::filesystem::remove_all(dir);
}

TEST(Cli, SingleCameraWritesIntoOutAndDumpsTheGraph) {
    auto dir = tempDir("cli-one");
    RunResult r = runPpr("capture --camera stairs --size 160x90 --frames 1 --dump-graph --set debug=albedo --out " + dir.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    auto report = readJson(dir / "report.json");
    EXPECT_EQ(report["settings"]["debug"], "albedo");
    EXPECT_EQ(report["camera"]["name"], "stairs");
    EXPECT_TRUE(std::filesystem::exists(dir / "graph.dot"));
    std::filesystem::remove_all(dir);
}

TEST(Cli, CompareEveryNamedCameraWritesMetricsAndContactSheets) {
    auto dir = tempDir("cli-compare");
    RunResult r = runPpr("compare --validation --size 320x180 --frames 1 --technique ppr --technique none --out " + dir.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    scene::Scene s = scene::loadGltf(PPR_DEFAULT_SCENE_FILE);
    auto summary = readJson(dir / "metrics.json");
    EXPECT_EQ(summary["validation_errors"], 0);
    for (const scene::NamedCamera& c : s.cameras) {
        auto m = readJson(dir / c.name / "metrics.json");
        EXPECT_EQ(m["validation_errors"], 0) << c.name;
        for (const char* t : {"ppr", "none"})
            for (const char* key : {"psnr_db", "psnr_reflection_db", "coverage", "gpu_ms"}) EXPECT_TRUE(m["techniques"][t].contains(key)) << t << key;
        EXPECT_EQ(m["reference"], "planar");
        EXPECT_GT(m["reference_run"]["gpu_ms"].get<double>(), 0.0);
        // PPR reflects; `none` covers nothing and scores lower (where the view has opaque reflections
        // to score: through the glass camera's window the puddle reflects only sky).
        if (m["techniques"]["ppr"]["scored_pixels"].get<uint64_t>() == 0) continue;
        EXPECT_GT(m["techniques"]["ppr"]["coverage"].get<double>(), 0.9) << c.name;
        EXPECT_EQ(m["techniques"]["none"]["coverage"].get<double>(), 0.0) << c.name;
        EXPECT_GT(m["techniques"]["ppr"]["psnr_db"].get<double>(), m["techniques"]["none"]["psnr_db"].get<double>()) << c.name;
        EXPECT_GT(m["techniques"]["ppr"]["gpu_ms"].get<double>(), 0.0);
        EXPECT_EQ(summary["cameras"][c.name]["ppr"]["coverage"], m["techniques"]["ppr"]["coverage"]);
        const util::Rgba8Image contact = util::readPng((dir / c.name / "contact.png").string());
        EXPECT_GT(contact.width, 3u * 320u) << "three columns: ppr, none, reference";
        EXPECT_GT(contact.height, 3u * 180u) << "three rows: final, reflection, error";
    }
    std::filesystem::remove_all(dir);
}

TEST(Cli, CaptureTechniquesRecordTheirPasses) {
    auto dir = tempDir("cli-tech");
    for (const char* t : {"ppr", "planar"}) {
        RunResult r = runPpr(std::string("capture --camera mirror --size 160x90 --frames 1 --technique ") + t + " --out " + (dir / t).string());
        ASSERT_EQ(r.exitCode, 0) << r.output;
        auto report = readJson(dir / t / "report.json");
        EXPECT_EQ(report["technique"], t);
        EXPECT_GT(report["technique_gpu_ms"].get<double>(), 0.0);
        EXPECT_TRUE(report["passes"].contains(std::string(t) == "ppr" ? "ppr.project" : "planar.clear")) << t;
    }
    auto ppr = readJson(dir / "ppr" / "report.json");
    for (const char* pass : {"ppr.clear", "ppr.project", "ppr.reflect"}) EXPECT_TRUE(ppr["passes"].contains(pass)) << pass;
    std::filesystem::remove_all(dir);
}

struct BadInput {
    const char* name;
    const char* args;
    const char* mustMention;
};

class CliBadInput : public ::testing::TestWithParam<BadInput> {};

TEST_P(CliBadInput, ExitsNonZeroWithOneLineNamingTheProblem) {
    RunResult r = runPpr(std::string("capture --size 64x36 --frames 1 --out /tmp/ppr-bad-input ") + GetParam().args);
    EXPECT_NE(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find(GetParam().mustMention), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("ppr: error:"), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find("Segmentation"), std::string::npos);
}

INSTANTIATE_TEST_SUITE_P(
    Cases, CliBadInput,
    ::testing::Values(BadInput{"unknown_set_key", "--set colour=red", "known keys: debug"}, BadInput{"bad_choice", "--set debug=sparkles", "expected one of"},
                      BadInput{"nan_number", "--set exposure=nan", "exposure"}, BadInput{"size_too_large", "--size 99999x5", "--size"},
                      BadInput{"size_not_wxh", "--size 12", "expected WxH"}, BadInput{"zero_frames", "--frames 0", "--frames"},
                      BadInput{"unknown_camera", "--camera nowhere", "known:"}, BadInput{"nan_camera", "--camera 1,2,3,nan,0", "--camera"},
                      BadInput{"missing_scene", "--scene /nonexistent/scene.gltf", "/nonexistent/scene.gltf"},
                      BadInput{"unknown_technique", "--technique raytracing", "available"}, BadInput{"unknown_option", "--bogus", "unknown option"},
                      BadInput{"ppr_size_beyond_encoding", "--size 4100x64", "4096"},
                      BadInput{"bad_toggle", "--set filter=2", "expected one of 0|1"},
                      BadInput{"nan_reflector", "--reflectors " PPR_TEST_DATA_DIR "/reflectors/bad_nan.json", "bad_nan.json"},
                      BadInput{"missing_reflectors", "--reflectors /nonexistent/r.json", "/nonexistent/r.json"},
                      BadInput{"gltf_index_out_of_range", "--scene /usr/share/assimp/models/glTF2/IndexOutOfRange/IndexOutOfRange.gltf", "IndexOutOfRange.gltf"},
                      BadInput{"gltf_missing_bin", "--scene /usr/share/assimp/models/glTF2/MissingBin/BoxTextured.gltf", "BoxTextured.gltf"},
                      BadInput{"gltf_infinite_positions", "--scene /usr/share/assimp/models/glTF2/BoxWithInfinites-glTF-Binary/BoxWithInfinites.glb",
                               "BoxWithInfinites.glb"}),
    [](const ::testing::TestParamInfo<BadInput>& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace ppr::test
