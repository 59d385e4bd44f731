// Bench report: technique cost sums, ratios to PPR and the floor, the hierarchy build alone, the
// slides' numbers, and the tables of bench.md, all from hand-made results (no GPU).
#include "bench/bench_report.hpp"

#include <gtest/gtest.h>

using namespace ppr::app;

namespace {

// The cost passes as the technique table attributes them (tested in unit/techniques): its own passes,
// tile classification for ppr and ssr-*, the depth hierarchy for ppr and ssr-hiz.
bool costs(const std::string& technique, const std::string& pass) {
    auto starts = [&](const std::string& p) { return pass.rfind(p, 0) == 0; };
    if (pass == technique || starts(technique + ".")) return true;
    if (starts("tiles.")) return technique == "ppr" || technique.rfind("ssr-", 0) == 0;
    return starts("hiz.") && (technique == "ppr" || technique == "ssr-hiz");
}

BenchTechnique technique(const std::string& name, std::map<std::string, double> passMs, std::optional<double> psnr = 30.0) {
    BenchTechnique t;
    t.name = name;
    t.passMs = std::move(passMs);
    for (const auto& [pass, ms] : t.passMs)
        if (costs(name, pass)) {
            t.costPasses.insert(pass);
            t.techniqueMs += ms;
        }
    t.frameMs = 10.0 + t.techniqueMs;
    if (psnr) {  // absent for the reference
        t.psnrDb = t.psnrReflectionDb = psnr;
        t.coverage = 0.5;
    }
    return t;
}

// Shared scene passes cost the same everywhere and count for no technique.
std::map<std::string, double> withScene(std::map<std::string, double> passMs) {
    passMs["gbuffer"] = 3.0;
    passMs["lighting"] = 2.0;
    return passMs;
}

BenchResults results(bool withFloor = true) {
    BenchResults r;
    r.header = {{"device", "test device"}, {"driver", "test"}, {"size", {320, 180}}, {"frames", 2}, {"warmup", 1}};
    r.techniquesCamera = "overview";
    r.techniques.push_back(technique("ppr", withScene({{"ppr.project", 0.5}, {"ppr.reflect", 0.25}, {"tiles.classify", 0.05},
                                                       {"hiz.build.0", 0.1}, {"hiz.build.1", 0.1}})));
    r.techniques.push_back(technique("ssr-brute", withScene({{"ssr-brute", 19.95}, {"tiles.classify", 0.05}})));
    r.techniques.push_back(technique("ssr-hiz", withScene({{"ssr-hiz", 2.0}, {"tiles.classify", 0.05}, {"hiz.build.0", 0.15},
                                                           {"hiz.build.1", 0.1}, {"hiz.build.2", 0.05}})));
    r.techniques.push_back(technique("planar", withScene({{"planar.gbuffer", 6.0}, {"planar.lighting", 4.0}}), std::nullopt));
    if (withFloor) r.techniques.push_back(technique("floor", withScene({{"floor", 0.5}})));
    return r;
}

const BenchTechnique& find(const BenchResults& r, const std::string& name) {
    for (const BenchTechnique& t : r.techniques)
        if (t.name == name) return t;
    throw std::runtime_error("no technique " + name);
}

size_t count(const std::string& text, const std::string& what) {
    size_t n = 0;
    for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
    return n;
}

}  // namespace

TEST(BenchReport, TechniqueSumCountsOwnTileAndHierarchyPasses) {
    const BenchResults r = results();
    EXPECT_DOUBLE_EQ(find(r, "ppr").techniqueMs, 1.0);  // project + reflect + tiles + hiz (the fallback's)
    EXPECT_DOUBLE_EQ(find(r, "ssr-brute").techniqueMs, 20.0);
    EXPECT_DOUBLE_EQ(find(r, "ssr-hiz").techniqueMs, 2.35);
    EXPECT_DOUBLE_EQ(find(r, "planar").techniqueMs, 10.0);
    EXPECT_DOUBLE_EQ(find(r, "floor").techniqueMs, 0.5);
}

TEST(BenchReport, HierarchyBuildIsTheSumOfHizPassesAndAbsentWithoutThem) {
    const BenchResults r = results();
    ASSERT_TRUE(hizBuildMs(find(r, "ssr-hiz")));
    EXPECT_DOUBLE_EQ(*hizBuildMs(find(r, "ssr-hiz")), 0.3);
    ASSERT_TRUE(hizBuildMs(find(r, "ppr")));
    EXPECT_DOUBLE_EQ(*hizBuildMs(find(r, "ppr")), 0.2);
    EXPECT_FALSE(hizBuildMs(find(r, "ssr-brute")));
    EXPECT_FALSE(hizBuildMs(find(r, "floor")));
}

TEST(BenchReport, PprCostSplitsIntoPlanarGlassAndFallbackThatAddUp) {
    const BenchTechnique ppr = technique("ppr", withScene({{"tiles.classify", 0.5}, {"ppr.project", 2.0}, {"ppr.reflect", 0.25},
                                                           {"ppr.glass.clear", 0.125}, {"ppr.glass.reflect", 1.0},
                                                           {"hiz.build.0", 0.375}, {"ppr.fallback", 0.75}}));
    const auto parts = pprCostParts(ppr);
    ASSERT_TRUE(parts);
    EXPECT_DOUBLE_EQ(parts->planar, 2.75);
    EXPECT_DOUBLE_EQ(parts->glass, 1.125);
    EXPECT_DOUBLE_EQ(parts->fallback, 1.125);
    EXPECT_DOUBLE_EQ(parts->planar + parts->glass + parts->fallback, ppr.techniqueMs);
    const BenchResults r = results();
    EXPECT_FALSE(pprCostParts(find(r, "ssr-hiz")));
    const nlohmann::json j = benchJson(r)["techniques"]["results"];
    EXPECT_DOUBLE_EQ(j["ppr"]["planar_gpu_ms"].get<double>(), 0.8);
    EXPECT_DOUBLE_EQ(j["ppr"]["fallback_gpu_ms"].get<double>(), 0.2);
    EXPECT_FALSE(j["ssr-hiz"].contains("planar_gpu_ms"));
}

TEST(BenchReport, RatiosToPprAndFloor) {
    const BenchResults r = results();
    EXPECT_DOUBLE_EQ(*benchRatio(r, find(r, "ssr-brute").techniqueMs, "ppr"), 20.0);
    EXPECT_DOUBLE_EQ(*benchRatio(r, find(r, "ppr").techniqueMs, "ppr"), 1.0);
    EXPECT_DOUBLE_EQ(*benchRatio(r, find(r, "ppr").techniqueMs, "floor"), 2.0);
    EXPECT_DOUBLE_EQ(*benchRatio(r, find(r, "floor").techniqueMs, "floor"), 1.0);
    EXPECT_DOUBLE_EQ(*benchRatio(r, find(r, "planar").techniqueMs, "floor"), 20.0);
}

TEST(BenchReport, RatioIsAbsentWhenTheReferenceDidNotRunOrTookNoTime) {
    const BenchResults noFloor = results(false);
    EXPECT_FALSE(benchRatio(noFloor, find(noFloor, "ppr").techniqueMs, "floor"));
    BenchResults freeFloor = results();
    for (BenchTechnique& t : freeFloor.techniques)
        if (t.name == "floor") t.techniqueMs = 0.0;
    EXPECT_FALSE(benchRatio(freeFloor, find(freeFloor, "ppr").techniqueMs, "floor"));
}

TEST(BenchReport, JsonHoldsRatiosHierarchyBuildAndScores) {
    const nlohmann::json j = benchJson(results());
    const nlohmann::json& t = j["techniques"]["results"];
    for (const char* name : {"ppr", "ssr-brute", "ssr-hiz", "planar", "floor"}) {
        ASSERT_TRUE(t.contains(name)) << name;
        for (const char* key : {"gpu_ms", "frame_gpu_ms", "passes", "ratio_to_ppr", "ratio_to_floor", "psnr_db", "psnr_reflection_db", "coverage"})
            EXPECT_TRUE(t[name].contains(key)) << name << " " << key;
    }
    EXPECT_DOUBLE_EQ(t["ssr-brute"]["ratio_to_ppr"].get<double>(), 20.0);
    EXPECT_DOUBLE_EQ(t["ppr"]["ratio_to_floor"].get<double>(), 2.0);
    EXPECT_DOUBLE_EQ(t["ssr-hiz"]["hiz_build_ms"].get<double>(), 0.3);
    EXPECT_DOUBLE_EQ(t["ppr"]["hiz_build_ms"].get<double>(), 0.2);
    EXPECT_FALSE(t["ssr-brute"].contains("hiz_build_ms"));
    EXPECT_TRUE(t["planar"]["psnr_db"].is_null());
    EXPECT_DOUBLE_EQ(t["ssr-hiz"]["passes"]["hiz.build.2"].get<double>(), 0.05);
}

TEST(BenchReport, JsonLeavesTheFloorRatioOutWithoutTheFloor) {
    const nlohmann::json j = benchJson(results(false));
    for (const auto& [name, e] : j["techniques"]["results"].items()) {
        EXPECT_FALSE(e.contains("ratio_to_floor")) << name;
        EXPECT_TRUE(e.contains("ratio_to_ppr")) << name;
    }
}

TEST(BenchReport, JsonHoldsTheSlidesNumbers) {
    const nlohmann::json s = benchJson(results())["techniques"]["slides"];
    EXPECT_EQ(s["size"], nlohmann::json({3840, 2160}));
    EXPECT_NE(s["device"].get<std::string>().find("1070"), std::string::npos);
    EXPECT_DOUBLE_EQ(s["results"]["ssr-brute"]["gpu_ms"].get<double>(), 20.6);
    EXPECT_DOUBLE_EQ(s["results"]["ssr-lowq"]["gpu_ms"].get<double>(), 0.95);
    EXPECT_DOUBLE_EQ(s["results"]["ppr"]["gpu_ms"].get<double>(), 0.95);
    EXPECT_DOUBLE_EQ(s["results"]["ssr-hiz"]["gpu_ms"].get<double>(), 3.55);  // the trace + the build, like ours
    EXPECT_DOUBLE_EQ(s["results"]["ssr-hiz"]["hiz_build_ms"].get<double>(), 0.35);
    EXPECT_NEAR(s["results"]["ssr-brute"]["ratio_to_ppr"].get<double>(), 20.6 / 0.95, 1e-12);
}

TEST(BenchReport, NoTechniquesNoTechniquesSection) {
    BenchResults r = results();
    r.techniques.clear();
    EXPECT_FALSE(benchJson(r).contains("techniques"));
    EXPECT_EQ(benchMarkdown(r, "ppr bench").find("## Techniques"), std::string::npos);
}

TEST(BenchReport, MarkdownTechniquesTable) {
    const std::string md = benchMarkdown(results(), "ppr bench --size 320x180");
    EXPECT_NE(md.find("| technique | GPU ms | × PPR | × floor | PSNR dB | reflection PSNR dB | coverage | frame ms |"), std::string::npos) << md;
    EXPECT_NE(md.find("| ssr-brute | 20.00 | 20.00 | 40.00 | 30.00 | 30.00 | 0.5000 | 30.00 |"), std::string::npos) << md;
    EXPECT_NE(md.find("| planar | 10.00 | 10.00 | 20.00 | ref | ref | ref | 20.00 |"), std::string::npos) << md;
    // ssr-hiz's hierarchy build alone, right under ssr-hiz.
    const size_t hiz = md.find("| ssr-hiz | 2.35 |");
    const size_t build = md.find("| ↳ ssr-hiz hierarchy build (hiz.*) | 0.30 | 0.30 | 0.60 |");
    ASSERT_NE(hiz, std::string::npos) << md;
    ASSERT_NE(build, std::string::npos) << md;
    EXPECT_EQ(md.find('\n', hiz) + 1, build);
}

TEST(BenchReport, MarkdownWithoutTheFloorShowsADash) {
    const std::string md = benchMarkdown(results(false), "ppr bench");
    EXPECT_NE(md.find("| ssr-brute | 20.00 | 20.00 | – |"), std::string::npos) << md;
}

TEST(BenchReport, MarkdownPerPassTableInFrameOrderWithOwnPassesBold) {
    BenchResults r = results();
    for (BenchTechnique& t : r.techniques) {  // frame order: scene passes, the technique's, composite
        t.passMs["composite"] = 1.0;
        t.passOrder = {"gbuffer", "lighting"};
        for (const auto& [name, ms] : t.passMs)
            if (name != "gbuffer" && name != "lighting" && name != "composite") t.passOrder.push_back(name);
        t.passOrder.push_back("composite");
    }
    const std::string md = benchMarkdown(r, "ppr bench");
    EXPECT_NE(md.find("| pass | ppr | ssr-brute | ssr-hiz | planar | floor |"), std::string::npos) << md;
    EXPECT_NE(md.find("| gbuffer | 3.000 | 3.000 | 3.000 | 3.000 | 3.000 |"), std::string::npos) << md;
    EXPECT_NE(md.find("| hiz.build.2 |  |  | **0.050** |  |  |"), std::string::npos) << md;
    EXPECT_NE(md.find("| tiles.classify | **0.050** | **0.050** | **0.050** |  |  |"), std::string::npos) << md;
    EXPECT_NE(md.find("| floor |  |  |  |  | **0.500** |"), std::string::npos) << md;
    const size_t lighting = md.find("| lighting |"), brute = md.find("| ssr-brute |  |"), floor = md.find("| floor |  |"),
                 composite = md.find("| composite |");
    ASSERT_NE(brute, std::string::npos) << md;
    EXPECT_LT(lighting, brute);
    EXPECT_LT(brute, floor);
    EXPECT_LT(floor, composite);
    EXPECT_EQ(count(md, "| composite |"), 1u);
}

TEST(BenchReport, MarkdownSlidesTable) {
    const std::string md = benchMarkdown(results(), "ppr bench");
    EXPECT_NE(md.find("| technique | slides GTX 1070 4K ms | slides × PPR | ours ms | ours × PPR |"), std::string::npos) << md;
    EXPECT_NE(md.find("| ssr-brute | 20.60 | 21.68 | 20.00 | 20.00 |"), std::string::npos) << md;
    EXPECT_NE(md.find("| ssr-hiz (with hierarchy build) | 3.55 | 3.74 | 2.35 | 2.35 |"), std::string::npos) << md;
    EXPECT_NE(md.find("| ↳ ssr-hiz hierarchy build | 0.35 | 0.37 | 0.30 | 0.30 |"), std::string::npos) << md;
    EXPECT_NE(md.find("| ssr-lowq | 0.95 | 1.00 | – | – |"), std::string::npos) << md;  // not measured here
}

TEST(BenchReport, TaaPassesAreReportedApartFromTheTechnique) {
    BenchResults r = results();
    r.techniques.push_back(technique("ppr@taa=1", withScene({{"ppr.project", 2.0}, {"ppr.reflect", 0.25}, {"taa.reflection", 0.5}, {"taa", 1.5}})));
    const BenchTechnique& withTaa = r.techniques.back();
    ASSERT_TRUE(taaMs(withTaa));
    EXPECT_DOUBLE_EQ(*taaMs(withTaa), 2.0);
    EXPECT_FALSE(taaMs(find(r, "ppr")));
    const nlohmann::json j = benchJson(r)["techniques"]["results"];
    EXPECT_DOUBLE_EQ(j["ppr@taa=1"]["taa_gpu_ms"].get<double>(), 2.0);
    EXPECT_DOUBLE_EQ(j["ppr@taa=1"]["taa_ratio_to_floor"].get<double>(), 2.0 / find(r, "floor").techniqueMs);
    EXPECT_FALSE(j["ppr"].contains("taa_gpu_ms"));
    EXPECT_NE(benchMarkdown(r, "ppr bench").find("TAA in ppr@taa=1"), std::string::npos);
}

TEST(BenchReport, MedianPerPassOverTheRoundsThatRanIt) {
    const std::map<std::string, double> m = medianPerPass({{{"a", 1.0}, {"b", 5.0}}, {{"a", 3.0}}, {{"a", 2.0}, {"b", 7.0}}});
    EXPECT_DOUBLE_EQ(m.at("a"), 2.0);
    EXPECT_DOUBLE_EQ(m.at("b"), 6.0);  // two rounds ran it: their mean
    EXPECT_TRUE(medianPerPass({}).empty());
}

// --rounds: each round's values, and ratios taken within each round, which the ratio of the medians
// over the rounds is not (here PPR doubles in round 2 while the floor does not).
TEST(BenchReport, RoundsGiveEachRoundsValuesAndTheRatiosWithinThem) {
    BenchResults plain = results();
    BenchResults r = plain;
    for (BenchTechnique& t : r.techniques) {
        std::map<std::string, double> second = t.passMs;
        if (t.name == "ppr")
            for (auto& [pass, ms] : second) ms *= 2.0;
        t.roundPassMs = {t.passMs, second};
    }
    ASSERT_EQ(techniqueRounds(r), 2u);
    EXPECT_DOUBLE_EQ(techniqueInRound(find(r, "ppr"), 1).techniqueMs, 2.0);
    const nlohmann::json j = benchJson(r)["techniques"]["results"];
    EXPECT_EQ(j["ppr"]["gpu_ms_rounds"], nlohmann::json({1.0, 2.0}));
    EXPECT_EQ(j["ppr"]["ratio_to_floor_rounds"], nlohmann::json({2.0, 4.0}));
    EXPECT_EQ(j["floor"]["ratio_to_ppr_rounds"], nlohmann::json({0.5, 0.25}));
    EXPECT_NEAR(j["ppr"]["planar_gpu_ms_rounds"][1].get<double>(), 1.6, 1e-12);  // project, reflect, tiles
    EXPECT_FALSE(j["floor"].contains("planar_gpu_ms_rounds"));
    EXPECT_FALSE(j["ppr"].contains("taa_gpu_ms_rounds"));
    EXPECT_EQ(j["ppr"]["passes_rounds"]["ppr.project"], nlohmann::json({0.5, 1.0}));

    BenchReflectorRow one, many;
    one.reflectors = 1;
    many.reflectors = 1024;
    one.roundProjectMs = {1.0, 2.0};
    many.roundProjectMs = {3.0, 5.0};
    one.roundReachMs = many.roundReachMs = {1.0, 1.0};
    r.reflectors = {one, many};
    EXPECT_EQ(benchJson(r)["sweeps"]["reflectors"]["rows"][1]["project_ms_rounds"], nlohmann::json({3.0, 5.0}));

    const std::string md = benchMarkdown(r, "ppr bench --rounds 2");
    EXPECT_NE(md.find("## Rounds"), std::string::npos) << md;
    // ssr-hiz costs 2.35 ms in both rounds.
    EXPECT_NE(md.find("| ppr | 1.00, 2.00 (1.50) | 1.00, 1.00 (1.00) | 2.00, 4.00 (3.00) | 0.43, 0.85 (0.64) |"), std::string::npos) << md;
    EXPECT_NE(md.find("| ↳ ppr planar part | 0.80, 1.60 (1.20) |"), std::string::npos) << md;
    EXPECT_NE(md.find("| floor | 0.50, 0.50 (0.50) | 0.50, 0.25 (0.38) | 1.00, 1.00 (1.00) | 0.21, 0.21 (0.21) |"), std::string::npos) << md;
    EXPECT_NE(md.find("| 1024 | 4.00, 6.00 (5.00) | 2.00, 2.00 (2.00) |"), std::string::npos) << md;

    // One round (the default): none of it.
    EXPECT_EQ(benchMarkdown(plain, "ppr bench").find("## Rounds"), std::string::npos);
    EXPECT_FALSE(benchJson(plain)["techniques"]["results"]["ppr"].contains("gpu_ms_rounds"));
}

// Issue 15's coverage measure: each view's indirect reflection pass (with its clear) over that of the
// view with the largest reflective fraction, whatever order the rows come in; per round too.
TEST(BenchReport, CoverageRowsGiveTheIndirectPassOverTheFullestViews) {
    BenchResults r = results();
    r.coverageScene = "stress:256";
    auto row = [](const std::string& camera, double fraction, bool indirect, double reflect, double clear) {
        BenchCoverageRow c;
        c.camera = camera;
        c.reflectiveTiles = fraction;
        c.indirect = indirect;
        c.reflectMs = reflect;
        c.clearMs = clear;
        return c;
    };
    r.coverage = {row("reflective_5", 0.065, true, 1.5, 0.5), row("reflective_5", 0.065, false, 10.0, 0.0),
                  row("reflective_100", 0.998, true, 19.5, 0.5), row("reflective_100", 0.998, false, 20.0, 0.0)};
    std::string md = benchMarkdown(r, "ppr bench --sweep coverage");
    EXPECT_NE(md.find("| indirect / whole screen | indirect / fullest view's |"), std::string::npos) << md;
    EXPECT_NE(md.find("| reflective_5 | 6.5 % | 1.50 (+ 0.50) | 10.00 | 0.20 | 0.10 |"), std::string::npos) << md;
    EXPECT_NE(md.find("| reflective_100 | 99.8 % | 19.50 (+ 0.50) | 20.00 | 1.00 | 1.00 |"), std::string::npos) << md;
    EXPECT_NE(md.find("over reflective_100's"), std::string::npos) << md;

    r.coverage[0].roundReflectMs = {1.5, 3.5};
    r.coverage[0].roundClearMs = {0.5, 0.5};
    r.coverage[1].roundReflectMs = {10.0, 10.0};
    r.coverage[2].roundReflectMs = {19.5, 39.5};
    r.coverage[2].roundClearMs = {0.5, 0.5};
    r.coverage[3].roundReflectMs = {20.0, 20.0};
    md = benchMarkdown(r, "ppr bench --sweep coverage --rounds 2");
    EXPECT_NE(md.find("| reflective_5 | 2.00, 4.00 (3.00) | 10.00, 10.00 (10.00) | 0.20, 0.40 (0.30) | 0.10, 0.10 (0.10) |"), std::string::npos) << md;
}
