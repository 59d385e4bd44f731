// Inputs fuzz_cli found (tests/data/fuzz/regressions/cli/, one argv word per line, as the fuzzer
// reads them): a control character in an argument, e.g. the "\r" a script saved with CRLF line ends
// passes, was echoed raw into the error, which then no longer printed as one line. Each must be
// refused with one std::runtime_error line that shows the character escaped.
#include "cli/cli.hpp"
#include "cli/scene_source.hpp"
#include "scene/stress_scene.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

using namespace ppr;

namespace {

const std::filesystem::path kDir = std::filesystem::path(PPR_TEST_DATA_DIR) / "fuzz" / "regressions" / "cli";

std::vector<std::string> words(const std::filesystem::path& file) {  // as tests/fuzz/fuzz_cli.cpp splits
    std::ifstream in(file, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    std::vector<std::string> out{"ppr"};
    std::string word;
    while (std::getline(text, word)) out.push_back(word);
    return out;
}

std::string parseError(const std::vector<std::string>& args) {
    std::vector<const char*> argv;
    for (const std::string& a : args) argv.push_back(a.c_str());
    try {
        app::parseCommandLine(int(argv.size()), argv.data());
    } catch (const std::runtime_error& e) {
        return e.what();
    }
    return "(accepted)";
}

bool oneLine(const std::string& s) { return s.find_first_of("\r\n") == std::string::npos; }

}  // namespace

TEST(CliFuzzRegressions, EverySavedInputIsRefusedWithOneLine) {
    size_t count = 0;
    for (const auto& entry : std::filesystem::directory_iterator(kDir)) {
        const std::vector<std::string> args = words(entry.path());
        const std::string msg = parseError(args);
        SCOPED_TRACE(entry.path().filename().string() + ": " + msg);
        if (msg == "(accepted)") {
            // Then the scene spec or the camera fails later, as fuzz_cli checks them: against a scene.
            std::vector<const char*> argv;
            for (const std::string& a : args) argv.push_back(a.c_str());
            const app::Options o = app::parseCommandLine(int(argv.size()), argv.data());
            int refused = 0;
            try {
                scene::parseStressSpec(o.scene);
            } catch (const std::runtime_error& e) {
                EXPECT_TRUE(oneLine(e.what())) << e.what();
                ++refused;
            }
            try {
                app::resolveCameras(scene::makeStressScene(1), o.camera);
            } catch (const std::runtime_error& e) {
                EXPECT_TRUE(oneLine(e.what())) << e.what();
                ++refused;
            }
            EXPECT_GT(refused, 0) << "accepted";
        } else {
            EXPECT_TRUE(oneLine(msg));
        }
        ++count;
    }
    EXPECT_GE(count, 4u);
}

TEST(CliFuzzRegressions, CrlfArgumentIsShownEscaped) {
    EXPECT_EQ(parseError({"ppr", "capture", "--size", "640x360\r"}), "--size 360\\r: expected a whole number");
    EXPECT_EQ(parseError({"ppr", "capture", "--frames\r"}), "unknown option '--frames\\r' (see ppr --help)");
    EXPECT_EQ(parseError({"ppr", "--set", "tiles=1\r"}), "--set tiles=1\\r: expected one of 0|1");
}

TEST(CliFuzzRegressions, StressSpecAndCameraNameStayOneLine) {
    try {
        scene::parseStressSpec("stress:4\r\n");
        ADD_FAILURE() << "accepted";
    } catch (const std::runtime_error& e) {
        EXPECT_TRUE(oneLine(e.what())) << e.what();
    }
    try {
        app::resolveCameras(scene::makeStressScene(1), "over\rview");
        ADD_FAILURE() << "accepted";
    } catch (const std::runtime_error& e) {
        EXPECT_TRUE(oneLine(e.what())) << e.what();
        EXPECT_NE(std::string(e.what()).find("over\\rview"), std::string::npos) << e.what();
    }
}

TEST(CliFuzzRegressions, PrintableEscapesControlCharactersOnly) {
    EXPECT_EQ(app::printable("a\tb\nc\rd\x01\x7f" "é"), "a\\tb\\nc\\rd\\x01\\x7fé");
}
