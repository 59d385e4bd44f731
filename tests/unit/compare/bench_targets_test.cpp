// Bench targets: the ratios docs/goals.md tracks, computed from hand-made results (no GPU), within
// each round when the run has rounds, and left out when their rows did not run.
#include "bench/bench_targets.hpp"

#include <gtest/gtest.h>

using namespace ppr::app;

namespace {

// A technique whose cost passes are all its passes.
BenchTechnique row(const std::string& name, std::map<std::string, double> passMs) {
    BenchTechnique t;
    t.name = name;
    t.passMs = std::move(passMs);
    for (const auto& [pass, ms] : t.passMs) {
        if (pass == "taa" || pass.rfind("taa.", 0) == 0) continue;  // TAA is never a technique's cost
        t.costPasses.insert(pass);
        t.techniqueMs += ms;
    }
    return t;
}

BenchResults techniques() {
    BenchResults r;
    r.techniques.push_back(row("ppr", {{"tiles.classify", 1.0}, {"ppr.project", 5.0}, {"ppr.reflect", 4.0}, {"ppr.glass.reflect", 2.0},
                                       {"hiz.build.0", 1.0}, {"ppr.fallback", 2.0}}));  // 15 ms; planar part 10
    r.techniques.push_back(row("ppr@holes=slides,facing=0", {{"ppr.project", 5.0}, {"ppr.reflect", 2.5}}));
    r.techniques.push_back(row("ppr@taa=1", {{"ppr.project", 5.0}, {"taa", 20.0}, {"taa.reflection", 10.0}}));
    r.techniques.push_back(row("ssr-hiz", {{"ssr-hiz.planar", 20.0}}));
    r.techniques.push_back(row("floor", {{"floor", 10.0}}));
    return r;
}

const BenchTarget& target(const std::vector<BenchTarget>& targets, const std::string& key) {
    for (const BenchTarget& t : targets)
        if (t.key == key) return t;
    throw std::runtime_error("no target " + key);
}

}  // namespace

TEST(BenchTargets, TechniqueRatiosAgainstTheirLimits) {
    const std::vector<BenchTarget> t = benchTargets(techniques());
    ASSERT_EQ(t.size(), 5u);  // no reflector or coverage sweep
    EXPECT_DOUBLE_EQ(target(t, "ppr_to_floor").value, 1.5);
    EXPECT_TRUE(target(t, "ppr_to_floor").met());
    EXPECT_DOUBLE_EQ(target(t, "ppr_planar_to_ssr_hiz").value, 0.5);  // tiles, project, reflect: 10 / 20, at the limit
    EXPECT_TRUE(target(t, "ppr_planar_to_ssr_hiz").met());
    EXPECT_DOUBLE_EQ(target(t, "classify_to_floor").value, 0.1);
    EXPECT_DOUBLE_EQ(target(t, "reflect_to_slides").value, 1.6);
    EXPECT_FALSE(target(t, "reflect_to_slides").met());
    EXPECT_DOUBLE_EQ(target(t, "taa_to_floor").value, 3.0);
    EXPECT_EQ(target(t, "taa_to_floor").measure, "TAA (`taa`, `taa.*`) of ppr@taa=1 / the floor pass");
    EXPECT_TRUE(target(t, "taa_to_floor").rounds.empty());
}

// Rows that did not run, or a floor that took no time, give no target rather than a wrong one.
TEST(BenchTargets, LeftOutWithoutTheirRows) {
    BenchResults r = techniques();
    r.techniques.erase(r.techniques.begin() + 1);  // no slides' row
    r.techniques.pop_back();                       // no floor
    std::vector<BenchTarget> t = benchTargets(r);
    ASSERT_EQ(t.size(), 1u);
    EXPECT_EQ(t[0].key, "ppr_planar_to_ssr_hiz");
    r.techniques.push_back(row("floor", {{"floor", 0.0}}));
    EXPECT_EQ(benchTargets(r).size(), 1u);
    EXPECT_TRUE(benchTargets(BenchResults{}).empty());
    EXPECT_EQ(benchTargetsMarkdown({}), "");
}

// With --rounds each ratio is taken within its round and the value is their median: here the
// floor's round 2 is slow, which a ratio of the medians would hide.
TEST(BenchTargets, RatiosWithinEachRound) {
    BenchResults r = techniques();
    for (BenchTechnique& t : r.techniques) {
        std::map<std::string, double> second = t.passMs, third = t.passMs;
        if (t.name == "floor") second["floor"] = 30.0;
        if (t.name == "ppr") third["ppr.project"] = 8.0;  // 18 ms
        t.roundPassMs = {t.passMs, second, third};
    }
    const BenchTarget toFloor = target(benchTargets(r), "ppr_to_floor");
    EXPECT_EQ(toFloor.rounds, (std::vector<double>{1.5, 0.5, 1.8}));
    EXPECT_DOUBLE_EQ(toFloor.value, 1.5);
    const nlohmann::json j = benchTargetsJson(benchTargets(r));
    EXPECT_EQ(j["ppr_to_floor"]["rounds"], nlohmann::json({1.5, 0.5, 1.8}));
    EXPECT_EQ(j["ppr_to_floor"]["limit"], 2.5);
    EXPECT_EQ(j["ppr_to_floor"]["met"], true);
    EXPECT_EQ(j["reflect_to_slides"]["met"], false);
}

// The sweeps' targets: 1 024 reflectors over one (tiles=1, projection with the reach pass), and the
// sparsest coverage view's indirect pass over the fullest's, per round when both rows have rounds.
TEST(BenchTargets, SweepRatios) {
    auto projection = [](uint32_t reflectors, bool tiles, double projectMs) {
        BenchReflectorRow row;
        row.reflectors = reflectors;
        row.tiles = tiles;
        row.projectMs = projectMs;
        row.reachMs = tiles ? 2.0 : 0.0;
        return row;
    };
    auto reflection = [](const std::string& camera, double fraction, bool indirect, double reflectMs) {
        BenchCoverageRow row;
        row.camera = camera;
        row.reflectiveTiles = fraction;
        row.indirect = indirect;
        row.reflectMs = reflectMs;
        row.clearMs = indirect ? 0.5 : 0.0;
        return row;
    };
    BenchResults r;
    r.reflectors = {projection(1, true, 4.0), projection(1024, false, 900.0), projection(1024, true, 10.0)};
    r.coverage = {reflection("reflective_5", 0.065, true, 1.5), reflection("reflective_5", 0.065, false, 12.0),
                  reflection("reflective_100", 0.998, true, 19.5)};
    std::vector<BenchTarget> t = benchTargets(r);
    ASSERT_EQ(t.size(), 2u);
    EXPECT_DOUBLE_EQ(target(t, "projection_1024_to_1").value, 2.0);
    EXPECT_FALSE(target(t, "projection_1024_to_1").met());
    EXPECT_DOUBLE_EQ(target(t, "reflect_sparsest_to_fullest").value, 0.1);
    EXPECT_TRUE(target(t, "reflect_sparsest_to_fullest").met());
    EXPECT_EQ(target(t, "reflect_sparsest_to_fullest").measure, "`ppr.reflect` indirect with its clear, reflective_5 / reflective_100");

    r.reflectors[0].roundProjectMs = {4.0, 8.0};
    r.reflectors[0].roundReachMs = {2.0, 2.0};
    r.reflectors[2].roundProjectMs = {10.0, 13.0};
    r.reflectors[2].roundReachMs = {2.0, 2.0};
    t = benchTargets(r);
    EXPECT_EQ(target(t, "projection_1024_to_1").rounds, (std::vector<double>{2.0, 1.5}));
    EXPECT_DOUBLE_EQ(target(t, "projection_1024_to_1").value, 1.75);

    const std::string md = benchTargetsMarkdown(t);
    EXPECT_NE(md.find("| `ppr.project` + `ppr.reach` at 1 024 reflectors / at 1 (tiles=1) | 1.75 (2.00, 1.50) | ≤ 1.50 | no |"),
              std::string::npos)
        << md;
    EXPECT_NE(md.find("| `ppr.reflect` indirect with its clear, reflective_5 / reflective_100 | 0.10 | ≤ 0.10 | yes |"), std::string::npos) << md;
    EXPECT_NE(md.find("`scripts/compare-timing.py` alternates the two scenes"), std::string::npos) << md;
    EXPECT_EQ(benchTargetsMarkdown(benchTargets(techniques())).find("compare-timing"), std::string::npos);  // only with that target
}
