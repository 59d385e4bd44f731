// The command line's bounds (docs/reliability.md "Bad input"): absurd sizes and frame counts are
// refused with one line naming the option and value; one-pixel-wide frames are valid.
#include "cli/cli.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace {

ppr::app::Options parse(const std::vector<std::string>& args) {
    std::vector<const char*> argv;
    for (const std::string& a : args) argv.push_back(a.c_str());
    return ppr::app::parseCommandLine(int(argv.size()), argv.data());
}

std::string errorOf(const std::vector<std::string>& args) {
    try {
        parse(args);
    } catch (const std::runtime_error& e) {
        return e.what();
    }
    return "(accepted)";
}

}  // namespace

TEST(CliLimits, OnePixelSidesAreValid) {
    const ppr::app::Options o = parse({"ppr", "capture", "--size", "1x4096"});
    EXPECT_EQ(o.width, 1u);
    EXPECT_EQ(o.height, 4096u);
    EXPECT_EQ(parse({"ppr", "capture", "--size", "17x9"}).height, 9u);
}

TEST(CliLimits, AbsurdSizesAndFrameCountsAreRefused) {
    EXPECT_EQ(errorOf({"ppr", "capture", "--size", "0x0"}), "--size 0: out of range (1..8192)");
    EXPECT_EQ(errorOf({"ppr", "capture", "--size", "-5x10"}), "--size -5: expected a whole number");
    EXPECT_EQ(errorOf({"ppr", "capture", "--size", "100000x100000"}), "--size 100000: out of range (1..8192)");
    EXPECT_EQ(errorOf({"ppr", "capture", "--frames", "0"}), "--frames 0: out of range (1..100000)");
    EXPECT_EQ(errorOf({"ppr", "capture", "--frames", "1e12"}), "--frames 1e12: expected a whole number");
    EXPECT_EQ(errorOf({"ppr", "capture", "--frames", "1000000000000"}), "--frames 1000000000000: out of range (1..100000)");
}

TEST(CliLimits, BenchRounds) {
    EXPECT_EQ(parse({"ppr", "bench"}).rounds, 1u);
    EXPECT_EQ(parse({"ppr", "bench", "--rounds", "3"}).rounds, 3u);
    EXPECT_EQ(errorOf({"ppr", "bench", "--rounds", "0"}), "--rounds 0: out of range (1..100)");
    EXPECT_EQ(errorOf({"ppr", "bench", "--rounds", "101"}), "--rounds 101: out of range (1..100)");
    EXPECT_EQ(errorOf({"ppr", "bench", "--rounds", "two"}), "--rounds two: expected a whole number");
    EXPECT_EQ(errorOf({"ppr", "capture", "--rounds", "2"}), "--rounds 2: only bench measures in rounds");
}

TEST(CliLimits, RenderScaleIsTheViewersAlone) {
    EXPECT_FALSE(parse({"ppr", "view"}).renderScale.has_value());  // auto: the device decides (render_scale.hpp)
    EXPECT_FALSE(parse({"ppr", "view", "--render-scale", "auto"}).renderScale.has_value());
    EXPECT_FLOAT_EQ(parse({"ppr", "view", "--render-scale", "0.5"}).renderScale.value_or(0.0f), 0.5f);
    EXPECT_FLOAT_EQ(parse({"ppr", "view", "--render-scale", "1"}).renderScale.value_or(0.0f), 1.0f);
    EXPECT_FLOAT_EQ(parse({"ppr", "--render-scale", "0.1"}).renderScale.value_or(0.0f), 0.1f);  // no command: the viewer with a display
    EXPECT_FLOAT_EQ(parse({"ppr", "capture", "--render-scale", "1"}).renderScale.value_or(0.0f), 1.0f);  // what capture does anyway
    EXPECT_EQ(errorOf({"ppr", "view", "--render-scale", "0.05"}), "--render-scale 0.05: out of range (0.1..1)");
    EXPECT_EQ(errorOf({"ppr", "view", "--render-scale", "2"}), "--render-scale 2: out of range (0.1..1)");
    EXPECT_EQ(errorOf({"ppr", "view", "--render-scale", "nan"}), "--render-scale nan: expected a number");
    EXPECT_EQ(errorOf({"ppr", "view", "--render-scale", "Auto"}), "--render-scale Auto: expected a number");
    EXPECT_EQ(errorOf({"ppr", "capture", "--render-scale", "auto"}), "(accepted)");  // the default, said out loud
    EXPECT_EQ(errorOf({"ppr", "capture", "--render-scale", "0.5"}),
              "--render-scale: only the viewer renders below its window's size (capture, compare and bench render at --size)");
}

TEST(CliLimits, FitOptions) {
    const ppr::app::Options o =
        parse({"ppr", "fit", "--scene", "s.gltf", "--materials", "floor|glass", "--max-roughness", "0.3", "--min-area", "2", "--out", "r.json"});
    EXPECT_EQ(o.mode, ppr::app::Mode::Fit);
    EXPECT_EQ(o.fitMaterials.value_or(""), "floor|glass");
    EXPECT_FLOAT_EQ(o.fitMaxRoughness.value_or(-1.0f), 0.3f);
    EXPECT_FLOAT_EQ(o.fitMinArea, 2.0f);
    EXPECT_TRUE(o.outGiven);
    EXPECT_FALSE(parse({"ppr", "fit"}).outGiven);
    EXPECT_EQ(errorOf({"ppr", "fit", "--max-roughness", "1.5"}), "--max-roughness 1.5: out of range (0..1)");
    EXPECT_EQ(errorOf({"ppr", "fit", "--min-area", "nan"}), "--min-area nan: expected a number");
    EXPECT_EQ(errorOf({"ppr", "fit", "--min-area", "1e99"}), "--min-area 1e99: expected a number");
    EXPECT_EQ(errorOf({"ppr", "fit", "--min-area", "-1"}), "--min-area -1: out of range (0..1e+10)");
    EXPECT_EQ(errorOf({"ppr", "capture", "--materials", "x"}), "--materials, --max-roughness, --min-area and --append belong to ppr fit");
    EXPECT_EQ(errorOf({"ppr", "view", "--append"}), "--materials, --max-roughness, --min-area and --append belong to ppr fit");
    EXPECT_FALSE(o.fitAppend);
    EXPECT_TRUE(parse({"ppr", "fit", "--append"}).fitAppend);
    EXPECT_EQ(errorOf({"ppr", "fit", "--out", ""}), "--out: expected a file name");
}
