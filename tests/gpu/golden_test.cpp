// Pictures that must not change: a new mode switched off must give the old images bit for bit. Each
// golden file (tests/data/golden/*.json) holds, per named camera, a hash of the decoded pixels of
// `ppr capture`'s final.png, made by an earlier build on the device named in the file:
//   ppr_before_normalmaps.json  PPR with normalmap=off fallback_env=0, recorded by the build of
//                               e32db7c, whose off+env0 images scripts/check-identical.sh had shown
//                               identical to PPR before normal maps (on this scene file);
//   ppr_before_hole_rule.json   PPR with the default settings, recorded by the same build: the slides'
//                               reflection pass, which the current build keeps as holes=slides
//                               facing=0 (issue 19's "holes=slides reproduces today's images";
//                               ce8b37b's defaults render as e32db7c's, fallback_env being 0).
// `current` holds the settings the current build adds to keep the old behaviour (options the
// recording build did not have; taa=0, the default, is spelled out: it must render today's images).
// On another device (another driver rasterizes and rounds differently) the test is skipped with a
// message: goldens are per device. To record a golden with another build:
//   PPR_GOLDEN_RECORD=path/to/ppr build/release/tests/gpu/ppr_gpu_tests --gtest_filter='Golden*'
#include "gpu_test_util.hpp"

#include "util/image_io.hpp"

#include <nlohmann/json.hpp>

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
    {"ppr_before_normalmaps.json", "--set normalmap=off --set fallback_env=0", "--set holes=slides --set facing=0 --set taa=0"},
    {"ppr_before_hole_rule.json", "", "--set holes=slides --set facing=0 --set taa=0"},
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

TEST(Golden, SwitchedOffModesKeepTheOldPictures) {
    for (const Golden& g : kGoldens) {
        const std::filesystem::path path = std::filesystem::path(PPR_TEST_DATA_DIR) / "golden" / g.file;
        const std::filesystem::path out = tempDir(std::string("golden-") + g.file);
        if (const char* recorder = std::getenv("PPR_GOLDEN_RECORD")) {
            std::ofstream(path) << captureHashes(recorder, g.sets, out).dump(2) << "\n";
            continue;
        }
        std::ifstream in(path);
        ASSERT_TRUE(in) << path;
        const nlohmann::json golden = nlohmann::json::parse(in);
        const nlohmann::json now = captureHashes(PPR_EXE, std::string(g.sets) + " " + g.current, out);
        if (now["device"] != golden["device"]) GTEST_SKIP() << g.file << " was recorded on " << golden["device"] << ", this is " << now["device"];
        ASSERT_EQ(now["cameras"].size(), golden["cameras"].size()) << g.file;
        for (const auto& [camera, hash] : golden["cameras"].items())
            EXPECT_EQ(now["cameras"][camera], hash) << g.file << ": camera " << camera << " (" << g.sets << " " << g.current << ") changed";
        std::filesystem::remove_all(out);
    }
}

}  // namespace
}  // namespace ppr::test
