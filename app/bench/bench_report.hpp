#pragma once
// What `ppr bench` measured, and its files: bench.json (the data), bench.md (tables with ratios
// measured in the same run) and bench.png (the sweeps' charts).
#include "ppr_common/tiles.h"

#include <nlohmann/json.hpp>

#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace ppr::app {

struct BenchTechnique {
    std::string name;
    double techniqueMs = 0.0;            // the sum of its costPasses
    std::set<std::string> costPasses;    // the passes that are its cost (isTechniquePass; bold in bench.md)
    double frameMs = 0.0;      // the whole frame
    std::map<std::string, double> passMs;
    std::vector<std::string> passOrder;  // execution order; empty = passMs' (alphabetical) order
    std::optional<double> psnrDb, psnrReflectionDb, coverage;  // against planar (absent for planar itself)
    // --rounds: each round's per-pass medians, in round order (passMs holds their medians per pass).
    std::vector<std::map<std::string, double>> roundPassMs;
};

struct BenchReflectorRow {  // reflectors sweep
    uint32_t reflectors = 0;
    bool tiles = true;
    double projectMs = 0.0, boundsMs = 0.0, reachMs = 0.0, techniqueMs = 0.0;  // reach: 0 unless tiles=1 indirect=1
    double projectionMs() const { return projectMs + reachMs; }                 // the projection with the pass that picks its tiles
    uint64_t pairs = 0, pairsUnculled = 0;
    std::vector<double> roundProjectMs, roundReachMs;  // --rounds: each round's (the fields above: their medians)
};

struct BenchCoverageRow {  // coverage sweep
    std::string camera;
    double reflectiveTiles = 0.0;  // fraction of screen tiles holding reflector pixels
    bool indirect = true;
    double reflectMs = 0.0, clearMs = 0.0, classifyMs = 0.0;
    std::vector<double> roundReflectMs, roundClearMs;  // --rounds: each round's (the fields above: their medians)
};

struct BenchResults {
    nlohmann::json header;  // device, size, frames, warm-up, environment
    std::string techniquesCamera;
    std::vector<BenchTechnique> techniques;
    std::map<std::string, std::string> skippedTechniques;  // technique → why this device cannot run it
    std::string reflectorsScene, reflectorsCamera;
    std::vector<BenchReflectorRow> reflectors;
    std::string coverageScene;
    std::vector<BenchCoverageRow> coverage;
};

// The median per pass over rounds (a pass missing from a round counts in the rounds that have it):
// bench's --rounds, whose rounds each give per-pass medians over their frames.
std::map<std::string, double> medianPerPass(const std::vector<std::map<std::string, double>>& rounds);
// The technique as round i measured it (its passMs that round's), for the per-round ratios.
BenchTechnique techniqueInRound(const BenchTechnique& technique, size_t round);
// The rounds every technique row has (0 without rounds).
size_t techniqueRounds(const BenchResults& results);

// The depth hierarchy build alone (hiz.* passes); absent when the technique built none.
std::optional<double> hizBuildMs(const BenchTechnique& technique);
// TAA's passes (`taa` and `taa.*`, a row run with --set taa=1, e.g. ppr@taa=1): the frame's and the
// reflection's history. Not part of the technique's GPU ms. Absent for a row without them.
std::optional<double> taaMs(const BenchTechnique& technique);
// PPR's GPU ms in three parts that add up to it: the planar part (tile classification and PPR's own
// passes), the glass atlas (ppr.glass.*) and the fallback (the depth hierarchy and ppr.fallback).
// Absent for a technique without a projection pass.
struct PprCostParts {
    double planar = 0.0, glass = 0.0, fallback = 0.0;
};
std::optional<PprCostParts> pprCostParts(const BenchTechnique& technique);
// `ms` over the GPU ms of the technique named `reference` (ppr, floor); absent when the reference
// was not measured or took no time.
std::optional<double> benchRatio(const BenchResults& results, double ms, const std::string& reference);

nlohmann::json benchJson(const BenchResults& results);
std::string benchMarkdown(const BenchResults& results, const std::string& commandLine);
// The sweeps side by side (those that ran); false when neither ran.
bool writeBenchPlot(const BenchResults& results, const std::string& path);

}  // namespace ppr::app
