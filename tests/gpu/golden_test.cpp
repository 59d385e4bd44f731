// Pictures that must not change: a new mode switched off must give the old images bit for bit. Each
// golden file (tests/data/golden/*.json) holds, per named camera, a hash of the decoded pixels of
// `ppr capture`'s final.png, made by an earlier build on the device named in the file:
//   ppr_before_normalmaps.json  PPR with normalmap=off fallback_env=0, recorded by the build of
//                               e32db7c, whose off+env0 images scripts/check-identical.sh had shown
//                               identical to PPR before normal maps (on this scene file);
//   ppr_before_hole_rule.json   PPR with the default settings, recorded by the same build: the slides'
//                               reflection pass, which the current build keeps as holes=slides
//                               facing=0 (issue 19's "holes=slides reproduces today's images";
//                               ce8b37b's defaults render as e32db7c's, fallback_env being 0);
//   taa_before_average.json     PPR with taa=1 after 8 frames, recorded by the build of be3e1c7, the
//                               last before the histories counted their frames (taa_average=0);
//   taa_before_still_range.json PPR with taa=1 after 24 frames (past a whole jitter cycle), recorded by
//                               the build of fc97632, the last before a still run's range and a still
//                               reflection kept whatever its path (taa_still_range=0, taa_still_keep=0).
// `current` holds the settings the current build adds to keep the old behaviour (options the
// recording build did not have; taa=0, the default, is spelled out: it must render today's images;
// fallback=ssr: PPR's holes unmarched, as before fallback=ssr_holes became the default;
// normal_refine=0: the slides' raymarch taps without the search for the crossing; normal_refine=walk:
// the search for it before the tangent planes, with the contact march on normal-mapped pixels).
// On another device (another driver rasterizes and rounds differently) the test is skipped with a
// message: goldens are per device. One device name can still round differently from host to host
// (llvmpipe compiles shaders for the CPU it runs on), so a file holds one or more recordings, each
// made by the old build on one host; the pictures must equal one recording's on every camera. To add
// a recording made on this host by another build (appended to the file):
//   PPR_GOLDEN_RECORD=path/to/ppr build/release/tests/gpu/ppr_gpu_tests --gtest_filter='Golden*'
#include "gpu_test_util.hpp"

#include "util/image_io.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdlib>
#include <fstream>

namespace ppr::test {
namespace {

struct Golden {
    const char* file;
    const char* sets;     // --set arguments, as given to both builds
    const char* current;  // and added for the current build
};
const Golden kGoldens[] = {
    {"ppr_before_normalmaps.json", "--set normalmap=off --set fallback_env=0", "--set holes=slides --set facing=0 --set splat=0 --set taa=0 --set fallback=ssr --set normal_refine=0"},
    {"ppr_before_hole_rule.json", "", "--set holes=slides --set facing=0 --set splat=0 --set taa=0 --set fallback=ssr --set normal_refine=0"},
    {"taa_before_average.json", "--set taa=1 --frames 8", "--set taa_average=0 --set normal_refine=walk"},
    {"taa_before_still_range.json", "--set taa=1 --frames 24", "--set taa_still_range=0 --set taa_still_keep=0"},
};
constexpr const char* kSize = "320x180";

uint64_t fnv1a(const std::vector<uint8_t>& bytes) {  // stable across builds and hosts
    uint64_t h = 1469598103934665603ull;
    for (uint8_t b : bytes) h = (h ^ b) * 1099511628211ull;
    return h;
}

// Captures every named camera with `exe` and returns camera → hash, plus the device name.
nlohmann::json captureHashes(const std::string& exe, const std::string& sets, const std::filesystem::path& out) {
    const std::string cmd = exe + " capture --technique ppr --size " + kSize + " --frames 1 " + sets + " --scene " +
                            PPR_DEFAULT_SCENE_FILE + " --out " + out.string() + " 2>&1";
    EXPECT_EQ(std::system(cmd.c_str()), 0) << cmd;
    std::ifstream summaryFile(out / "summary.json");
    const nlohmann::json summary = nlohmann::json::parse(summaryFile);
    nlohmann::json result = {{"device", summary.at("device")}, {"size", kSize}, {"sets", sets}, {"cameras", nlohmann::json::object()}};
    for (const auto& [camera, info] : summary.at("cameras").items()) {
        char hex[17];
        std::snprintf(hex, sizeof hex, "%016llx", (unsigned long long)fnv1a(util::readPng((out / camera / "final.png").string()).pixels));
        result["cameras"][camera] = hex;
    }
    return result;
}

// The recordings a golden file holds: {"recordings": [...]}, or one recording as the whole file.
std::vector<nlohmann::json> recordingsOf(const std::filesystem::path& path) {
    std::ifstream in(path);
    if (!in) return {};
    const nlohmann::json file = nlohmann::json::parse(in);
    if (!file.contains("recordings")) return {file};
    return file.at("recordings").get<std::vector<nlohmann::json>>();
}

TEST(Golden, SwitchedOffModesKeepTheOldPictures) {
    for (const Golden& g : kGoldens) {
        const std::filesystem::path path = std::filesystem::path(PPR_TEST_DATA_DIR) / "golden" / g.file;
        const std::filesystem::path out = tempDir(std::string("golden-") + g.file);
        std::vector<nlohmann::json> recordings = recordingsOf(path);
        if (const char* recorder = std::getenv("PPR_GOLDEN_RECORD")) {
            const nlohmann::json recording = captureHashes(recorder, g.sets, out);
            if (std::find(recordings.begin(), recordings.end(), recording) == recordings.end()) recordings.push_back(recording);
            std::ofstream(path) << nlohmann::json{{"recordings", recordings}}.dump(2) << "\n";
            continue;
        }
        ASSERT_FALSE(recordings.empty()) << path;
        const nlohmann::json now = captureHashes(PPR_EXE, std::string(g.sets) + " " + g.current, out);
        std::vector<nlohmann::json> sameDevice;
        for (const nlohmann::json& r : recordings)
            if (r.at("device") == now["device"]) sameDevice.push_back(r);
        if (sameDevice.empty()) GTEST_SKIP() << g.file << " was recorded on " << recordings.front()["device"] << ", this is " << now["device"];
        const bool matchesOne = std::any_of(sameDevice.begin(), sameDevice.end(), [&](const nlohmann::json& r) { return r.at("cameras") == now["cameras"]; });
        if (!matchesOne) {
            // Name the cameras that differ from the recording nearest to these pictures.
            const nlohmann::json* nearest = &sameDevice.front();
            size_t fewest = SIZE_MAX;
            for (const nlohmann::json& r : sameDevice) {
                size_t differing = 0;
                for (const auto& [camera, hash] : r.at("cameras").items()) differing += now["cameras"].value(camera, "") != hash;
                if (differing < fewest) {
                    fewest = differing;
                    nearest = &r;
                }
            }
            ADD_FAILURE() << g.file << ": the pictures equal none of its " << sameDevice.size() << " recording(s) on this device";
            for (const auto& [camera, hash] : nearest->at("cameras").items())
                EXPECT_EQ(now["cameras"].value(camera, ""), hash) << g.file << ": camera " << camera << " (" << g.sets << " " << g.current << ") changed";
        }
        std::filesystem::remove_all(out);
    }
}

}  // namespace
}  // namespace ppr::test
