// util/driver_defects on the device: the context reads the subgroup size; PPR on lavapipe's default 8
// lanes carries no driver warning; and where the CPU takes 512-bit rows (AVX-512), lavapipe run at 16
// lanes (LP_NATIVE_VECTOR_WIDTH=512) still projects wrongly and PPR says so, on stderr and in
// report.json. If a Mesa update fixed that, the picture check below fails: the warning would be stale.
#include "gpu_test_util.hpp"
#include "util/driver_defects.hpp"

namespace ppr::test {
namespace {

struct Capture {
    RunResult run;
    nlohmann::json report;
    util::Rgba8Image final;
};

Capture capturePuddles(const std::filesystem::path& dir) {
    Capture c;
    c.run = runPpr("capture --validation --technique ppr --camera puddles --size 160x90 --frames 1 --out " + dir.string());
    if (c.run.exitCode != 0) return c;
    c.report = readJson(dir / "report.json");
    c.final = util::readPng((dir / "final.png").string());
    return c;
}

TEST(DriverDefects, PprWarnsOnlyWhereLavapipeRunsAWidthItProjectsWrongly) {
    vk::ContextOptions o;
    const vk::DeviceInfo info = vk::Context::create(o)->info();
    const bool lavapipe = info.type == "cpu" && info.name.starts_with("llvmpipe");
    EXPECT_GT(info.subgroupSize, 0u) << info.name;
    if (lavapipe && !std::getenv("LP_NATIVE_VECTOR_WIDTH")) {
        EXPECT_EQ(info.subgroupSize, 8u) << info.name;
    }

    auto dir = tempDir("driver-defects");
    Capture asIs = capturePuddles(dir / "default");
    ASSERT_EQ(asIs.run.exitCode, 0) << asIs.run.output;
    EXPECT_EQ(asIs.report["validation_errors"], 0);
    EXPECT_EQ(asIs.report["warnings"].size(), util::lavapipeWidthWarning(info.type, info.name, info.subgroupSize).empty() ? 0u : 1u)
        << asIs.report["warnings"].dump();

    if (lavapipe && __builtin_cpu_supports("avx512f")) {
        ScopedEnv wide("LP_NATIVE_VECTOR_WIDTH", "512");
        Capture sixteen = capturePuddles(dir / "sixteen");
        ASSERT_EQ(sixteen.run.exitCode, 0) << sixteen.run.output;
        EXPECT_NE(sixteen.run.output.find("ppr: warning: llvmpipe runs 16-lane rows here (LP_NATIVE_VECTOR_WIDTH=512)"), std::string::npos)
            << sixteen.run.output;
        ASSERT_EQ(sixteen.report["warnings"].size(), 1u);
        EXPECT_NE(sixteen.report["warnings"][0].get<std::string>().find("LP_NATIVE_VECTOR_WIDTH=512"), std::string::npos);
        EXPECT_FALSE(identical(asIs.final, sixteen.final)) << "16 lanes project as 8 do: the driver is fixed, drop the warning";
    }
    std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace ppr::test
