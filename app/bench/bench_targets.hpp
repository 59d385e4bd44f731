#pragma once
// The project's performance targets (docs/goals.md), computed from what one `ppr bench` run
// measured: each a ratio the run can give (PPR over the floor pass, its planar part over ssr-hiz,
// 1 024 reflectors over one, ...), its limit, and whether this run met it. With --rounds, the ratio
// is taken within each round and the value is their median, as on a machine whose speed drifts.
#include "bench/bench_report.hpp"

#include <string>
#include <vector>

namespace ppr::app {

struct BenchTarget {
    std::string key;      // bench.json "targets" key
    std::string measure;  // what is divided by what, for bench.md
    double limit = 0.0;   // met when value <= limit
    double value = 0.0;   // the median of `rounds`, or the single run's ratio
    std::vector<double> rounds;  // the ratio within each round (empty without --rounds)
    bool met() const { return value <= limit; }
};

// The targets this run has the rows for, in docs/goals.md's order; a target whose rows did not run
// (or took no time) is left out.
std::vector<BenchTarget> benchTargets(const BenchResults& results);

nlohmann::json benchTargetsJson(const std::vector<BenchTarget>& targets);
// bench.md's section: empty when no target could be computed.
std::string benchTargetsMarkdown(const std::vector<BenchTarget>& targets);

}  // namespace ppr::app
