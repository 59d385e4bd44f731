#include "bench/bench_report.hpp"

#include "bench/bench_plot.hpp"
#include "bench/bench_targets.hpp"
#include "metrics/fixed_text.hpp"
#include "metrics/median.hpp"

#include <algorithm>
#include <functional>
#include <set>

namespace ppr::app {
namespace {

std::string fixedOr(const std::optional<double>& v, int digits, const std::string& absent) { return v ? fixedText(*v, digits) : absent; }

const BenchReflectorRow* findRow(const BenchResults& r, uint32_t n, bool tiles) {
    for (const BenchReflectorRow& row : r.reflectors)
        if (row.reflectors == n && row.tiles == tiles) return &row;
    return nullptr;
}

const BenchCoverageRow* findRow(const BenchResults& r, const std::string& camera, bool indirect) {
    for (const BenchCoverageRow& row : r.coverage)
        if (row.camera == camera && row.indirect == indirect) return &row;
    return nullptr;
}

std::vector<uint32_t> reflectorCounts(const BenchResults& r) {
    std::vector<uint32_t> out;
    for (const BenchReflectorRow& row : r.reflectors)
        if (out.empty() || out.back() != row.reflectors) out.push_back(row.reflectors);
    return out;
}

std::vector<std::string> coverageCameras(const BenchResults& r) {
    std::vector<std::string> out;
    for (const BenchCoverageRow& row : r.coverage)
        if (out.empty() || out.back() != row.camera) out.push_back(row.camera);
    return out;
}

// The indirect row of the view with the largest reflective fraction: issue 15 divides each view's
// indirect reflection pass (with its clear) by that one's, so the cost should follow the fraction.
const BenchCoverageRow* fullestIndirectRow(const BenchResults& r) {
    const BenchCoverageRow* fullest = nullptr;
    for (const BenchCoverageRow& row : r.coverage)
        if (row.indirect && (!fullest || row.reflectiveTiles > fullest->reflectiveTiles)) fullest = &row;
    return fullest;
}

nlohmann::json numberOrNull(const std::optional<double>& v) { return v ? nlohmann::json(*v) : nlohmann::json(nullptr); }

// Sum of the passes `counts` selects.
double sumPasses(const std::map<std::string, double>& passMs, const std::function<bool(const std::string&)>& counts) {
    double sum = 0.0;
    for (const auto& [name, ms] : passMs)
        if (counts(name)) sum += ms;
    return sum;
}

const BenchTechnique* findTechnique(const BenchResults& r, const std::string& name) {
    for (const BenchTechnique& t : r.techniques)
        if (t.name == name) return &t;
    return nullptr;
}

// The PPR slides' timings (GTX 1070, 3840x2160), for context only: another GPU, scene and size.
// ssr-hiz's is its 3.2 ms trace plus the 0.35 ms hierarchy build, as our GPU ms includes hiz.* too.
struct SlideTiming {
    const char* technique;
    double ms;
    std::optional<double> hizBuildMs;
};
const SlideTiming kSlides[] = {{"ppr", 0.95, {}}, {"ssr-brute", 20.6, {}}, {"ssr-lowq", 0.95, {}}, {"ssr-hiz", 3.55, 0.35}};
constexpr double kSlidesPprMs = 0.95;
constexpr const char* kSlidesDevice = "NVIDIA GeForce GTX 1070";
constexpr uint32_t kSlidesSize[] = {3840, 2160};

nlohmann::json slidesJson() {
    nlohmann::json results = nlohmann::json::object();
    for (const SlideTiming& s : kSlides) {
        nlohmann::json e = {{"gpu_ms", s.ms}, {"ratio_to_ppr", s.ms / kSlidesPprMs}};
        if (s.hizBuildMs) e["hiz_build_ms"] = *s.hizBuildMs;
        results[s.technique] = e;
    }
    return {{"device", kSlidesDevice}, {"size", kSlidesSize}, {"results", results}};
}

nlohmann::json techniqueJson(const BenchResults& r, const BenchTechnique& t) {
    nlohmann::json e = {{"gpu_ms", t.techniqueMs}, {"frame_gpu_ms", t.frameMs}, {"passes", t.passMs}};
    if (const auto ratio = benchRatio(r, t.techniqueMs, "ppr")) e["ratio_to_ppr"] = *ratio;
    if (const auto ratio = benchRatio(r, t.techniqueMs, "floor")) e["ratio_to_floor"] = *ratio;
    if (const auto build = hizBuildMs(t)) e["hiz_build_ms"] = *build;
    if (const auto taa = taaMs(t)) {
        e["taa_gpu_ms"] = *taa;
        e["taa_ratio_to_floor"] = numberOrNull(benchRatio(r, *taa, "floor"));
    }
    if (const auto parts = pprCostParts(t)) {
        e["planar_gpu_ms"] = parts->planar;
        e["glass_gpu_ms"] = parts->glass;
        e["fallback_gpu_ms"] = parts->fallback;
    }
    e["psnr_db"] = numberOrNull(t.psnrDb);
    e["psnr_reflection_db"] = numberOrNull(t.psnrReflectionDb);
    e["coverage"] = numberOrNull(t.coverage);
    return e;
}

// The results as round i measured them (--rounds): each technique's passes that round.
BenchResults resultsInRound(const BenchResults& r, size_t round) {
    BenchResults out = r;
    for (BenchTechnique& t : out.techniques) t = techniqueInRound(t, round);
    return out;
}

// A value of each round's results (absent in any round: no list).
std::optional<std::vector<double>> perRound(const std::vector<BenchResults>& rounds,
                                            const std::function<std::optional<double>(const BenchResults&)>& value) {
    std::vector<double> out;
    for (const BenchResults& round : rounds) {
        const std::optional<double> v = value(round);
        if (!v) return std::nullopt;
        out.push_back(*v);
    }
    return out;
}

// PPR's planar part alone (pprCostParts); absent for a technique without a projection pass.
std::optional<double> planarPartMs(const BenchTechnique& t) {
    const auto parts = pprCostParts(t);
    return parts ? std::optional<double>(parts->planar) : std::nullopt;
}

// The per-round lists of a technique's measures (bench.json "<key>_rounds"), for --rounds.
void addRounds(nlohmann::json& e, const std::vector<BenchResults>& rounds, const BenchTechnique& technique) {
    auto add = [&](const std::string& key, const std::function<std::optional<double>(const BenchResults&, const BenchTechnique&)>& value) {
        const auto list = perRound(rounds, [&](const BenchResults& round) { return value(round, *findTechnique(round, technique.name)); });
        if (list) e[key + "_rounds"] = *list;
    };
    add("gpu_ms", [](const BenchResults&, const BenchTechnique& t) { return std::optional<double>(t.techniqueMs); });
    add("ratio_to_ppr", [](const BenchResults& r, const BenchTechnique& t) { return benchRatio(r, t.techniqueMs, "ppr"); });
    add("ratio_to_floor", [](const BenchResults& r, const BenchTechnique& t) { return benchRatio(r, t.techniqueMs, "floor"); });
    add("planar_gpu_ms", [](const BenchResults&, const BenchTechnique& t) { return planarPartMs(t); });
    add("taa_gpu_ms", [](const BenchResults&, const BenchTechnique& t) { return taaMs(t); });
    // Every pass, round by round (a pass some round did not run: 0 there).
    nlohmann::json passes = nlohmann::json::object();
    for (const auto& [pass, ms] : technique.passMs) {  // every pass of any round (medianPerPass)
        std::vector<double> list;
        for (const auto& round : technique.roundPassMs) {
            const auto it = round.find(pass);
            list.push_back(it == round.end() ? 0.0 : it->second);
        }
        passes[pass] = list;
    }
    e["passes_rounds"] = passes;
}

std::string techniquesTable(const BenchResults& r) {
    std::string md = "| technique | GPU ms | × PPR | × floor | PSNR dB | reflection PSNR dB | coverage | frame ms |\n"
                     "|---|---:|---:|---:|---:|---:|---:|---:|\n";
    // GPU ms and its ratios: the cells every row of this table starts with.
    auto cost = [&](const std::string& label, double ms) {
        return "| " + label + " | " + fixedText(ms, 2) + " | " + fixedOr(benchRatio(r, ms, "ppr"), 2, "–") + " | " +
               fixedOr(benchRatio(r, ms, "floor"), 2, "–") + " | ";
    };
    for (const BenchTechnique& t : r.techniques) {
        md += cost(t.name, t.techniqueMs) + fixedOr(t.psnrDb, 2, "ref") + " | " + fixedOr(t.psnrReflectionDb, 2, "ref") + " | " +
              fixedOr(t.coverage, 4, "ref") + " | " + fixedText(t.frameMs, 2) + " |\n";
        // The hierarchy build alone, as the slides quote it apart from the trace.
        if (const auto build = hizBuildMs(t)) md += cost("↳ " + t.name + " hierarchy build (hiz.*)", *build) + "| | | |\n";
        if (const auto parts = pprCostParts(t)) {
            md += cost("↳ " + t.name + " planar part (tiles.*, ppr.*)", parts->planar) + "| | | |\n";
            md += cost("↳ " + t.name + " glass atlas (ppr.glass.*)", parts->glass) + "| | | |\n";
            md += cost("↳ " + t.name + " fallback (hiz.*, ppr.fallback)", parts->fallback) + "| | | |\n";
        }
    }
    return md;
}

std::vector<std::string> executionOrder(const BenchTechnique& t) {
    if (!t.passOrder.empty()) return t.passOrder;
    std::vector<std::string> order;
    for (const auto& [name, ms] : t.passMs) order.push_back(name);
    return order;
}

// Every technique's passes in one execution order: a pass comes after those that run before it in
// any technique; ties (and disagreements) go to the pass seen first, so the shared scene passes lead
// and each technique's own passes follow in column order.
std::vector<std::string> passRows(const BenchResults& r) {
    std::vector<std::string> seen;
    std::map<std::string, std::set<std::string>> predecessors;  // pass → the passes right before it somewhere
    for (const BenchTechnique& t : r.techniques) {
        const std::vector<std::string> order = executionOrder(t);
        for (size_t i = 0; i < order.size(); ++i) {
            if (std::find(seen.begin(), seen.end(), order[i]) == seen.end()) seen.push_back(order[i]);
            if (i > 0) predecessors[order[i]].insert(order[i - 1]);
        }
    }
    std::vector<std::string> rows;
    std::set<std::string> placed;
    auto isPlaced = [&](const std::string& p) { return placed.count(p) > 0; };
    auto isReady = [&](const std::string& p) { return !isPlaced(p) && std::all_of(predecessors[p].begin(), predecessors[p].end(), isPlaced); };
    while (rows.size() < seen.size()) {
        auto next = std::find_if(seen.begin(), seen.end(), isReady);
        if (next == seen.end()) next = std::find_if_not(seen.begin(), seen.end(), isPlaced);  // orders disagree: a cycle
        rows.push_back(*next);
        placed.insert(*next);
    }
    return rows;
}

std::string passesTable(const BenchResults& r) {
    std::string md = "| pass |", rule = "|---|";
    for (const BenchTechnique& t : r.techniques) {
        md += " " + t.name + " |";
        rule += "---:|";
    }
    md += "\n" + rule + "\n";
    for (const std::string& pass : passRows(r)) {
        md += "| " + pass + " |";
        for (const BenchTechnique& t : r.techniques) {
            const auto it = t.passMs.find(pass);
            const std::string ms = it == t.passMs.end() ? "" : fixedText(it->second, 3);
            md += " " + (!ms.empty() && t.costPasses.count(pass) ? "**" + ms + "**" : ms) + " |";
        }
        md += "\n";
    }
    return md;
}

std::string slidesTable(const BenchResults& r) {
    std::string md = "| technique | slides GTX 1070 4K ms | slides × PPR | ours ms | ours × PPR |\n|---|---:|---:|---:|---:|\n";
    auto line = [&](const std::string& label, double slidesMs, const std::optional<double>& oursMs) {
        md += "| " + label + " | " + fixedText(slidesMs, 2) + " | " + fixedText(slidesMs / kSlidesPprMs, 2) + " | " + fixedOr(oursMs, 2, "–") + " | " +
              fixedOr(oursMs ? benchRatio(r, *oursMs, "ppr") : std::nullopt, 2, "–") + " |\n";
    };
    for (const SlideTiming& s : kSlides) {
        const BenchTechnique* t = findTechnique(r, s.technique);
        line(s.technique + std::string(s.hizBuildMs ? " (with hierarchy build)" : ""), s.ms,
             t ? std::optional<double>(t->techniqueMs) : std::nullopt);
        if (s.hizBuildMs) line(std::string("↳ ") + s.technique + " hierarchy build", *s.hizBuildMs, t ? hizBuildMs(*t) : std::nullopt);
    }
    return md;
}

// "a, b, c (median m)": a measure over the rounds.
std::string roundList(const std::vector<double>& values, int digits) {
    std::string out;
    for (double v : values) out += (out.empty() ? "" : ", ") + fixedText(v, digits);
    return out + " (" + fixedText(median(values), digits) + ")";
}

// bench.md's per-round tables (--rounds): each measure as every round gave it and their median, the
// ratios taken within each round (what an interleaved comparison on a noisy machine should quote).
std::string roundsSection(const BenchResults& r) {
    std::string md;
    const size_t n = techniqueRounds(r);
    if (n >= 2) {
        std::vector<BenchResults> rounds;
        for (size_t i = 0; i < n; ++i) rounds.push_back(resultsInRound(r, i));
        md += "### Per round (" + std::to_string(n) + " rounds, each measuring every technique in turn; median in brackets; × ssr-hiz: "
              "issue 15's planar part against Hi-Z SSR)\n\n"
              "| technique | GPU ms | × PPR | × floor | × ssr-hiz |\n|---|---|---|---|---|\n";
        auto line = [&](const std::string& label, const std::function<std::optional<double>(const BenchResults&)>& ms) {
            const auto values = perRound(rounds, ms);
            if (!values) return;
            auto ratios = [&](const std::string& reference) {
                const auto list = perRound(rounds, [&](const BenchResults& round) -> std::optional<double> {
                    const auto v = ms(round);
                    return v ? benchRatio(round, *v, reference) : std::nullopt;
                });
                return list ? roundList(*list, 2) : std::string("–");
            };
            md += "| " + label + " | " + roundList(*values, 2) + " | " + ratios("ppr") + " | " + ratios("floor") + " | " + ratios("ssr-hiz") + " |\n";
        };
        for (const BenchTechnique& t : r.techniques) {
            const std::string name = t.name;
            auto technique = [name](const BenchResults& round) { return findTechnique(round, name); };
            line(name, [technique](const BenchResults& round) { return std::optional<double>(technique(round)->techniqueMs); });
            line("↳ " + name + " planar part", [technique](const BenchResults& round) { return planarPartMs(*technique(round)); });
            line("↳ " + name + " TAA (not in its GPU ms)", [technique](const BenchResults& round) { return taaMs(*technique(round)); });
        }
        md += "\n";
    }
    const BenchReflectorRow* first = r.reflectors.empty() ? nullptr : findRow(r, reflectorCounts(r).front(), true);
    if (first && first->roundProjectMs.size() >= 2) {
        md += "### Reflector count per round (`ppr.project` + `ppr.reach`, tiles=1; median in brackets)\n\n"
              "| reflectors | ms | / (N=1) |\n|---:|---|---|\n";
        auto projection = [](const BenchReflectorRow& row) {
            std::vector<double> out;
            for (size_t i = 0; i < row.roundProjectMs.size() && i < row.roundReachMs.size(); ++i)
                out.push_back(row.roundProjectMs[i] + row.roundReachMs[i]);
            return out;
        };
        const std::vector<double> base = projection(*first);
        for (uint32_t count : reflectorCounts(r)) {
            const BenchReflectorRow* on = findRow(r, count, true);
            if (!on) continue;
            const std::vector<double> ms = projection(*on);
            std::vector<double> ratios;
            for (size_t i = 0; i < ms.size() && i < base.size(); ++i)
                if (base[i] > 0.0) ratios.push_back(ms[i] / base[i]);
            md += "| " + std::to_string(count) + " | " + roundList(ms, 2) + " | " + (ratios.empty() ? "–" : roundList(ratios, 2)) + " |\n";
        }
        md += "\n";
    }
    if (!r.coverage.empty() && r.coverage.front().roundReflectMs.size() >= 2) {
        md += "### Reflective screen fraction per round (`ppr.reflect` ms; median in brackets)\n\n"
              "| camera | indirect=1 (+ clear) | indirect=0 | indirect / whole screen | indirect / fullest view's |\n|---|---|---|---|---|\n";
        auto indirectMs = [](const BenchCoverageRow* row) {
            std::vector<double> ms;
            for (size_t i = 0; row && i < row->roundReflectMs.size() && i < row->roundClearMs.size(); ++i)
                ms.push_back(row->roundReflectMs[i] + row->roundClearMs[i]);
            return ms;
        };
        const std::vector<double> fullestMs = indirectMs(fullestIndirectRow(r));
        for (const std::string& cam : coverageCameras(r)) {
            const BenchCoverageRow* on = findRow(r, cam, true);
            const BenchCoverageRow* off = findRow(r, cam, false);
            const std::vector<double> onMs = indirectMs(on);
            std::vector<double> ratios, toFullest;
            for (size_t i = 0; i < onMs.size(); ++i) {
                if (off && i < off->roundReflectMs.size() && off->roundReflectMs[i] > 0.0) ratios.push_back(onMs[i] / off->roundReflectMs[i]);
                if (i < fullestMs.size() && fullestMs[i] > 0.0) toFullest.push_back(onMs[i] / fullestMs[i]);
            }
            md += "| " + cam + " | " + (onMs.empty() ? "–" : roundList(onMs, 2)) + " | " +
                  (off && !off->roundReflectMs.empty() ? roundList(off->roundReflectMs, 2) : "–") + " | " +
                  (ratios.empty() ? "–" : roundList(ratios, 2)) + " | " + (toFullest.empty() ? "–" : roundList(toFullest, 2)) + " |\n";
        }
        md += "\n";
    }
    return md;
}

}  // namespace

std::optional<double> hizBuildMs(const BenchTechnique& t) {
    auto isHiz = [](const std::string& pass) { return pass.rfind("hiz.", 0) == 0; };
    if (std::none_of(t.passMs.begin(), t.passMs.end(), [&](const auto& p) { return isHiz(p.first); })) return std::nullopt;
    return sumPasses(t.passMs, isHiz);
}

std::optional<double> taaMs(const BenchTechnique& t) {
    auto isTaa = [](const std::string& pass) { return pass == "taa" || pass.rfind("taa.", 0) == 0; };
    if (std::none_of(t.passMs.begin(), t.passMs.end(), [&](const auto& p) { return isTaa(p.first); })) return std::nullopt;
    return sumPasses(t.passMs, isTaa);
}

std::optional<PprCostParts> pprCostParts(const BenchTechnique& t) {
    if (!t.passMs.count("ppr.project")) return std::nullopt;
    PprCostParts parts;
    for (const auto& [pass, ms] : t.passMs) {
        if (!t.costPasses.count(pass)) continue;
        if (pass.rfind("ppr.glass.", 0) == 0) parts.glass += ms;
        else if (pass.rfind("hiz.", 0) == 0 || pass.rfind("ppr.fallback", 0) == 0) parts.fallback += ms;  // with .holes
        else parts.planar += ms;
    }
    return parts;
}

std::optional<double> benchRatio(const BenchResults& r, double ms, const std::string& reference) {
    const BenchTechnique* ref = findTechnique(r, reference);
    if (!ref || ref->techniqueMs <= 0.0) return std::nullopt;
    return ms / ref->techniqueMs;
}

std::map<std::string, double> medianPerPass(const std::vector<std::map<std::string, double>>& rounds) {
    std::map<std::string, std::vector<double>> values;
    for (const auto& round : rounds)
        for (const auto& [pass, ms] : round) values[pass].push_back(ms);
    std::map<std::string, double> out;
    for (auto& [pass, list] : values) out[pass] = median(std::move(list));
    return out;
}

BenchTechnique techniqueInRound(const BenchTechnique& t, size_t round) {
    BenchTechnique r = t;
    r.passMs = t.roundPassMs.at(round);
    r.techniqueMs = sumPasses(r.passMs, [&](const std::string& pass) { return t.costPasses.count(pass) > 0; });
    r.roundPassMs.clear();
    return r;
}

size_t techniqueRounds(const BenchResults& r) {
    if (r.techniques.empty()) return 0;
    size_t n = r.techniques.front().roundPassMs.size();
    for (const BenchTechnique& t : r.techniques) n = std::min(n, t.roundPassMs.size());
    return n;
}

nlohmann::json benchJson(const BenchResults& r) {
    nlohmann::json j = r.header;
    if (!r.techniques.empty()) {
        std::vector<BenchResults> rounds;
        for (size_t i = 0; i < techniqueRounds(r); ++i) rounds.push_back(resultsInRound(r, i));
        nlohmann::json t = nlohmann::json::object();
        for (const BenchTechnique& row : r.techniques) {
            t[row.name] = techniqueJson(r, row);
            if (!rounds.empty()) addRounds(t[row.name], rounds, row);
        }
        j["techniques"] = {{"camera", r.techniquesCamera}, {"results", t}, {"slides", slidesJson()}};
        if (!r.skippedTechniques.empty()) j["techniques"]["skipped"] = r.skippedTechniques;
    }
    if (!r.reflectors.empty()) {
        nlohmann::json rows = nlohmann::json::array();
        for (const BenchReflectorRow& row : r.reflectors) {
            rows.push_back({{"reflectors", row.reflectors},
                            {"tiles", row.tiles ? 1 : 0},
                            {"project_ms", row.projectMs},
                            {"bounds_ms", row.boundsMs},
                            {"reach_ms", row.reachMs},
                            {"technique_ms", row.techniqueMs},
                            {"reflector_tile_pairs", row.pairs},
                            {"reflector_tile_pairs_unculled", row.pairsUnculled}});
            if (!row.roundProjectMs.empty()) {
                rows.back()["project_ms_rounds"] = row.roundProjectMs;
                rows.back()["reach_ms_rounds"] = row.roundReachMs;
            }
        }
        j["sweeps"]["reflectors"] = {{"scene", r.reflectorsScene}, {"camera", r.reflectorsCamera}, {"rows", rows}};
    }
    if (!r.coverage.empty()) {
        nlohmann::json rows = nlohmann::json::array();
        for (const BenchCoverageRow& row : r.coverage) {
            rows.push_back({{"camera", row.camera},
                            {"reflective_tiles", row.reflectiveTiles},
                            {"indirect", row.indirect ? 1 : 0},
                            {"reflect_ms", row.reflectMs},
                            {"reflection_clear_ms", row.clearMs},
                            {"classify_ms", row.classifyMs}});
            if (!row.roundReflectMs.empty()) {
                rows.back()["reflect_ms_rounds"] = row.roundReflectMs;
                rows.back()["reflection_clear_ms_rounds"] = row.roundClearMs;
            }
        }
        j["sweeps"]["coverage"] = {{"scene", r.coverageScene}, {"rows", rows}};
    }
    if (const std::vector<BenchTarget> targets = benchTargets(r); !targets.empty()) j["targets"] = benchTargetsJson(targets);
    return j;
}

std::string benchMarkdown(const BenchResults& r, const std::string& commandLine) {
    const nlohmann::json& h = r.header;
    std::string md = "# ppr bench\n\n`" + commandLine + "`\n\n";
    md += "Device: " + h.value("device", std::string()) + " (" + h.value("driver", std::string()) + "), " +
          std::to_string(h["size"][0].get<uint32_t>()) + "x" + std::to_string(h["size"][1].get<uint32_t>()) + ", median of " +
          std::to_string(h.value("frames", 0u)) + " frames after " + std::to_string(h.value("warmup", 0u)) + " warm-up frames" +
          (h.value("rounds", 1u) > 1 ? ", then the median of " + std::to_string(h.value("rounds", 1u)) + " rounds (see Rounds)" : "") + ".\n\n";
    if (!r.techniques.empty()) {
        md += "## Techniques (camera " + r.techniquesCamera + ")\n\n";
        md += "GPU ms: the technique's own passes (bold below; tile classification `tiles.*` for ppr and ssr-*, the depth "
              "hierarchy `hiz.*` for ssr-hiz and ppr's fallback; with one `ppr.reach` invocation per tile, a CPU device's default, "
              "that pass stores the hierarchy's levels 1-4 and counts in ppr's planar part). × PPR / × floor: GPU ms over ppr's / floor's (floor: the "
              "least any screen-space reflection costs; it draws none). PSNR and coverage against planar; frame ms: the whole "
              "frame.\n\n";
        md += techniquesTable(r) + "\n";
        for (const auto& [name, why] : r.skippedTechniques) md += "Not run: " + name + " (" + why + ")\n\n";
        for (const BenchTechnique& t : r.techniques)
            if (const auto taa = taaMs(t))
                md += "TAA in " + t.name + " (taa, taa.*; not in its GPU ms): " + fixedText(*taa, 2) + " ms, × floor " +
                      fixedOr(benchRatio(r, *taa, "floor"), 2, "–") + "\n\n";
        md += "### Per pass (GPU ms; bold: counted in the technique's GPU ms)\n\n" + passesTable(r) + "\n";
        md += std::string("### Against the slides (") + kSlidesDevice + " at " + std::to_string(kSlidesSize[0]) + "x" +
              std::to_string(kSlidesSize[1]) + "; another GPU, scene and size: compare the ratios)\n\n" + slidesTable(r) + "\n";
    }
    if (!r.reflectors.empty()) {
        md += "## Reflector count (" + r.reflectorsScene + ", camera " + r.reflectorsCamera + "): `ppr.project` (+ `ppr.reach`) ms\n\n";
        md += "| reflectors | tiles=1 | tiles=0 | tiles=0 / tiles=1 | tiles=1 / (N=1) | pairs kept (tiles=1) | pairs without culling |\n"
              "|---:|---:|---:|---:|---:|---:|---:|\n";
        const BenchReflectorRow* first = findRow(r, reflectorCounts(r).front(), true);
        auto projection = [](const BenchReflectorRow& row) {
            return row.reachMs > 0 ? fixedText(row.projectMs, 2) + " (+ " + fixedText(row.reachMs, 2) + ")" : fixedText(row.projectMs, 2);
        };
        for (uint32_t n : reflectorCounts(r)) {
            const BenchReflectorRow* on = findRow(r, n, true);
            const BenchReflectorRow* off = findRow(r, n, false);
            md += "| " + std::to_string(n) + " | " + (on ? projection(*on) : "–") + " | " + (off ? fixedText(off->projectMs, 2) : "–") +
                  " | " + (on && off && on->projectionMs() > 0 ? fixedText(off->projectionMs() / on->projectionMs(), 2) : "–") + " | " +
                  (on && first && first->projectionMs() > 0 ? fixedText(on->projectionMs() / first->projectionMs(), 2) : "–") + " | " +
                  (on ? std::to_string(on->pairs) : "–") + " | " + (on ? std::to_string(on->pairsUnculled) : "–") + " |\n";
        }
        md += "\n";
    }
    if (!r.coverage.empty()) {
        md += "## Reflective screen fraction (" + r.coverageScene + "): `ppr.reflect` ms\n\n";
        md += "| camera | reflective tiles | indirect=1 (+ clear) | indirect=0 | indirect / whole screen | indirect / fullest view's |\n"
              "|---|---:|---:|---:|---:|---:|\n";
        const BenchCoverageRow* fullest = fullestIndirectRow(r);
        const double fullestMs = fullest ? fullest->reflectMs + fullest->clearMs : 0.0;
        for (const std::string& cam : coverageCameras(r)) {
            const BenchCoverageRow* on = findRow(r, cam, true);
            const BenchCoverageRow* off = findRow(r, cam, false);
            const double onMs = on ? on->reflectMs + on->clearMs : 0.0;
            md += "| " + cam + " | " + (on ? fixedText(on->reflectiveTiles * 100.0, 1) + " %" : "–") + " | " +
                  (on ? fixedText(on->reflectMs, 2) + " (+ " + fixedText(on->clearMs, 2) + ")" : "–") + " | " + (off ? fixedText(off->reflectMs, 2) : "–") +
                  " | " + (on && off && off->reflectMs > 0 ? fixedText(onMs / off->reflectMs, 2) : "–") + " | " +
                  (on && fullestMs > 0 ? fixedText(onMs / fullestMs, 2) : "–") + " |\n";
        }
        if (fullest) md += "\nIndirect / fullest view's: issue 15's measure, each view's indirect pass (with its clear) over " + fullest->camera + "'s.\n";
        md += "\n";
    }
    md += benchTargetsMarkdown(benchTargets(r));
    const std::string rounds = roundsSection(r);
    if (!rounds.empty()) md += "## Rounds\n\n" + rounds;
    return md;
}

bool writeBenchPlot(const BenchResults& r, const std::string& path) {
    std::vector<util::Rgba8Image> charts;
    if (!r.reflectors.empty()) {
        PlotSpec spec;
        spec.title = "ppr.project (+ ppr.reach) vs reflector count";
        spec.xLabel = "mirror tiles (reflectors)";
        spec.yLabel = "GPU ms";
        spec.logX = true;
        for (bool tiles : {true, false}) {
            PlotSeries s;
            s.name = tiles ? "tiles=1 (culling)" : "tiles=0 (all per pixel)";
            for (const BenchReflectorRow& row : r.reflectors)
                if (row.tiles == tiles) {
                    s.x.push_back(row.reflectors);
                    s.y.push_back(row.projectionMs());
                }
            if (!s.x.empty()) spec.series.push_back(s);
        }
        charts.push_back(renderPlot(spec, 720, 460));
    }
    if (!r.coverage.empty()) {
        PlotSpec spec;
        spec.title = "ppr.reflect vs reflective fraction";
        spec.xLabel = "reflective screen tiles (%)";
        spec.yLabel = "GPU ms";
        for (bool indirect : {true, false}) {
            PlotSeries s;
            s.name = indirect ? "indirect=1 (+ clear)" : "indirect=0 (whole screen)";
            for (const BenchCoverageRow& row : r.coverage)
                if (row.indirect == indirect) {
                    s.x.push_back(row.reflectiveTiles * 100.0);
                    s.y.push_back(row.reflectMs + (indirect ? row.clearMs : 0.0));
                }
            if (!s.x.empty()) spec.series.push_back(s);
        }
        charts.push_back(renderPlot(spec, 720, 460));
    }
    if (charts.empty()) return false;
    util::writePng(path, sideBySide(charts));
    return true;
}

}  // namespace ppr::app
