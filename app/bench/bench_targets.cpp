#include "bench/bench_targets.hpp"

#include "metrics/median.hpp"
#include "metrics/fixed_text.hpp"

#include <functional>
#include <optional>

namespace ppr::app {
namespace {

std::optional<double> divide(double a, double b) { return b > 0.0 ? std::optional<double>(a / b) : std::nullopt; }

// A technique row as the whole run or one round measured it.
using RowLookup = std::function<std::optional<BenchTechnique>(const std::string& name)>;
using TechniqueRatio = std::function<std::optional<double>(const RowLookup& row)>;

RowLookup rowsOf(const BenchResults& r, std::optional<size_t> round) {
    return [&r, round](const std::string& name) -> std::optional<BenchTechnique> {
        for (const BenchTechnique& t : r.techniques)
            if (t.name == name) return round ? techniqueInRound(t, *round) : t;
        return std::nullopt;
    };
}

// A target from the techniques sweep: the ratio within each round (with --rounds) or of the run.
std::optional<BenchTarget> fromTechniques(const BenchResults& r, BenchTarget target, const TechniqueRatio& ratio) {
    const size_t rounds = techniqueRounds(r);
    if (rounds < 2) {
        const std::optional<double> v = ratio(rowsOf(r, std::nullopt));
        if (!v) return std::nullopt;
        target.value = *v;
        return target;
    }
    for (size_t i = 0; i < rounds; ++i) {
        const std::optional<double> v = ratio(rowsOf(r, i));
        if (!v) return std::nullopt;
        target.rounds.push_back(*v);
    }
    target.value = median(target.rounds);
    return target;
}

// A target from two rows of a sweep: `numerator` over `denominator`, each given as the run's value
// and each round's (the rounds only when both have at least two).
std::optional<BenchTarget> fromSweepRows(BenchTarget target, double numerator, const std::vector<double>& numeratorRounds,
                                         double denominator, const std::vector<double>& denominatorRounds) {
    if (numeratorRounds.size() >= 2 && numeratorRounds.size() == denominatorRounds.size()) {
        for (size_t i = 0; i < numeratorRounds.size(); ++i) {
            const std::optional<double> v = divide(numeratorRounds[i], denominatorRounds[i]);
            if (!v) return std::nullopt;
            target.rounds.push_back(*v);
        }
        target.value = median(target.rounds);
        return target;
    }
    const std::optional<double> v = divide(numerator, denominator);
    if (!v) return std::nullopt;
    target.value = *v;
    return target;
}

std::vector<double> sumRounds(const std::vector<double>& a, const std::vector<double>& b) {
    std::vector<double> out;
    for (size_t i = 0; i < a.size() && i < b.size(); ++i) out.push_back(a[i] + b[i]);
    return out;
}

const BenchReflectorRow* culledRow(const BenchResults& r, uint32_t reflectors) {
    for (const BenchReflectorRow& row : r.reflectors)
        if (row.reflectors == reflectors && row.tiles) return &row;
    return nullptr;
}

// The first row run with TAA (--set taa=1 or name@taa=1): its `taa` passes against the floor.
std::optional<std::string> taaRowName(const BenchResults& r) {
    for (const BenchTechnique& t : r.techniques)
        if (taaMs(t)) return t.name;
    return std::nullopt;
}

}  // namespace

std::vector<BenchTarget> benchTargets(const BenchResults& r) {
    std::vector<BenchTarget> out;
    auto add = [&out](const std::optional<BenchTarget>& t) {
        if (t) out.push_back(*t);
    };
    add(fromTechniques(r, {"ppr_to_floor", "PPR's GPU ms / the floor pass's", 2.5}, [](const RowLookup& row) -> std::optional<double> {
        const auto ppr = row("ppr"), floor = row("floor");
        return ppr && floor ? divide(ppr->techniqueMs, floor->techniqueMs) : std::nullopt;
    }));
    add(fromTechniques(r, {"ppr_planar_to_ssr_hiz", "PPR's planar part / ssr-hiz's GPU ms", 0.5}, [](const RowLookup& row) -> std::optional<double> {
        const auto ppr = row("ppr"), hiz = row("ssr-hiz");
        const auto parts = ppr ? pprCostParts(*ppr) : std::nullopt;
        return parts && hiz ? divide(parts->planar, hiz->techniqueMs) : std::nullopt;
    }));
    add(fromTechniques(r, {"classify_to_floor", "`tiles.classify` (ppr) / the floor pass", 0.3}, [](const RowLookup& row) -> std::optional<double> {
        const auto ppr = row("ppr"), floor = row("floor");
        if (!ppr || !floor || !ppr->passMs.count("tiles.classify")) return std::nullopt;
        return divide(ppr->passMs.at("tiles.classify"), floor->techniqueMs);
    }));
    const BenchReflectorRow *one = culledRow(r, 1), *many = culledRow(r, 1024);
    if (one && many)
        add(fromSweepRows({"projection_1024_to_1", "`ppr.project` + `ppr.reach` at 1 024 reflectors / at 1 (tiles=1)", 1.5},
                          many->projectionMs(), sumRounds(many->roundProjectMs, many->roundReachMs), one->projectionMs(),
                          sumRounds(one->roundProjectMs, one->roundReachMs)));
    const BenchCoverageRow *sparsest = nullptr, *fullest = nullptr;
    for (const BenchCoverageRow& row : r.coverage) {
        if (!row.indirect) continue;
        if (!sparsest || row.reflectiveTiles < sparsest->reflectiveTiles) sparsest = &row;
        if (!fullest || row.reflectiveTiles > fullest->reflectiveTiles) fullest = &row;
    }
    if (sparsest && fullest && sparsest != fullest)
        add(fromSweepRows({"reflect_sparsest_to_fullest",
                           "`ppr.reflect` indirect with its clear, " + sparsest->camera + " / " + fullest->camera, 0.10},
                          sparsest->reflectMs + sparsest->clearMs, sumRounds(sparsest->roundReflectMs, sparsest->roundClearMs),
                          fullest->reflectMs + fullest->clearMs, sumRounds(fullest->roundReflectMs, fullest->roundClearMs)));
    const std::string slides = "ppr@holes=slides,facing=0";
    add(fromTechniques(r, {"reflect_to_slides", "`ppr.reflect`, ppr / " + slides, 1.25}, [&slides](const RowLookup& row) -> std::optional<double> {
        const auto ppr = row("ppr"), old = row(slides);
        if (!ppr || !old || !ppr->passMs.count("ppr.reflect") || !old->passMs.count("ppr.reflect")) return std::nullopt;
        return divide(ppr->passMs.at("ppr.reflect"), old->passMs.at("ppr.reflect"));
    }));
    if (const auto name = taaRowName(r))
        add(fromTechniques(r, {"taa_to_floor", "TAA (`taa`, `taa.*`) of " + *name + " / the floor pass", 1.0},
                           [name = *name](const RowLookup& row) -> std::optional<double> {
                               const auto taa = row(name), floor = row("floor");
                               const auto ms = taa ? taaMs(*taa) : std::nullopt;
                               return ms && floor ? divide(*ms, floor->techniqueMs) : std::nullopt;
                           }));
    return out;
}

nlohmann::json benchTargetsJson(const std::vector<BenchTarget>& targets) {
    nlohmann::json j = nlohmann::json::object();
    for (const BenchTarget& t : targets) {
        nlohmann::json e = {{"measure", t.measure}, {"limit", t.limit}, {"value", t.value}, {"met", t.met()}};
        if (!t.rounds.empty()) e["rounds"] = t.rounds;
        j[t.key] = e;
    }
    return j;
}

std::string benchTargetsMarkdown(const std::vector<BenchTarget>& targets) {
    if (targets.empty()) return "";
    std::string md = "## Targets\n\nThe project's performance targets that this run's rows give (docs/goals.md; stated for the "
                     "default scene's overview at 1280x720 and 1920x1080): the ratio, within each round with --rounds (their "
                     "median first), against its limit.\n\n"
                     "| target | this run | limit | met |\n|---|---|---:|---|\n";
    for (const BenchTarget& t : targets) {
        std::string value = fixedText(t.value, 2);
        if (!t.rounds.empty()) {
            value += " (";
            for (size_t i = 0; i < t.rounds.size(); ++i) value += (i ? ", " : "") + fixedText(t.rounds[i], 2);
            value += ")";
        }
        md += "| " + t.measure + " | " + value + " | ≤ " + fixedText(t.limit, 2) + " | " + (t.met() ? "yes" : "no") + " |\n";
    }
    for (const BenchTarget& t : targets)
        if (t.key == "projection_1024_to_1")
            md += "\nThe reflector sweep measures its 1 and 1 024 rows tens of seconds apart, and one slow row moves "
                  "this ratio: `scripts/compare-timing.py` alternates the two scenes capture by capture (docs/performance.md).\n";
    return md + "\n";
}

}  // namespace ppr::app
