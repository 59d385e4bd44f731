#include "bench_report.hpp"

#include "bench_plot.hpp"

#include <cstdio>

namespace ppr::app {
namespace {

std::string fixed(double v, int digits) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.*f", digits, v);
    return buf;
}

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

}  // namespace

nlohmann::json benchJson(const BenchResults& r) {
    nlohmann::json j = r.header;
    if (!r.techniques.empty()) {
        nlohmann::json t = nlohmann::json::object();
        double pprMs = 0.0;
        for (const BenchTechnique& row : r.techniques)
            if (row.name == "ppr") pprMs = row.techniqueMs;
        for (const BenchTechnique& row : r.techniques) {
            nlohmann::json e = {{"gpu_ms", row.techniqueMs}, {"frame_gpu_ms", row.frameMs}, {"passes", row.passMs}};
            if (pprMs > 0.0) e["ratio_to_ppr"] = row.techniqueMs / pprMs;
            e["psnr_db"] = row.psnrDb ? nlohmann::json(*row.psnrDb) : nlohmann::json(nullptr);
            e["psnr_reflection_db"] = row.psnrReflectionDb ? nlohmann::json(*row.psnrReflectionDb) : nlohmann::json(nullptr);
            e["coverage"] = row.coverage ? nlohmann::json(*row.coverage) : nlohmann::json(nullptr);
            t[row.name] = e;
        }
        j["techniques"] = {{"camera", r.techniquesCamera}, {"results", t}};
    }
    if (!r.reflectors.empty()) {
        nlohmann::json rows = nlohmann::json::array();
        for (const BenchReflectorRow& row : r.reflectors)
            rows.push_back({{"reflectors", row.reflectors},
                            {"tiles", row.tiles ? 1 : 0},
                            {"project_ms", row.projectMs},
                            {"bounds_ms", row.boundsMs},
                            {"technique_ms", row.techniqueMs},
                            {"reflector_tile_pairs", row.pairs},
                            {"reflector_tile_pairs_unculled", row.pairsUnculled}});
        j["sweeps"]["reflectors"] = {{"scene", r.reflectorsScene}, {"camera", r.reflectorsCamera}, {"rows", rows}};
    }
    if (!r.coverage.empty()) {
        nlohmann::json rows = nlohmann::json::array();
        for (const BenchCoverageRow& row : r.coverage)
            rows.push_back({{"camera", row.camera},
                            {"reflective_tiles", row.reflectiveTiles},
                            {"indirect", row.indirect ? 1 : 0},
                            {"reflect_ms", row.reflectMs},
                            {"reflection_clear_ms", row.clearMs},
                            {"classify_ms", row.classifyMs}});
        j["sweeps"]["coverage"] = {{"scene", r.coverageScene}, {"rows", rows}};
    }
    return j;
}

std::string benchMarkdown(const BenchResults& r, const std::string& commandLine) {
    const nlohmann::json& h = r.header;
    std::string md = "# ppr bench\n\n`" + commandLine + "`\n\n";
    md += "Device: " + h.value("device", std::string()) + " (" + h.value("driver", std::string()) + "), " +
          std::to_string(h["size"][0].get<uint32_t>()) + "x" + std::to_string(h["size"][1].get<uint32_t>()) + ", median of " +
          std::to_string(h.value("frames", 0u)) + " frames after " + std::to_string(h.value("warmup", 0u)) + " warm-up frames.\n\n";
    if (!r.techniques.empty()) {
        double pprMs = 0.0;
        for (const BenchTechnique& t : r.techniques)
            if (t.name == "ppr") pprMs = t.techniqueMs;
        md += "## Techniques (camera " + r.techniquesCamera + ")\n\n";
        md += "| technique | technique ms | frame ms | × PPR | PSNR dB | reflection PSNR dB | coverage |\n|---|---:|---:|---:|---:|---:|---:|\n";
        for (const BenchTechnique& t : r.techniques) {
            md += "| " + t.name + " | " + fixed(t.techniqueMs, 2) + " | " + fixed(t.frameMs, 2) + " | " +
                  (pprMs > 0.0 ? fixed(t.techniqueMs / pprMs, 2) : std::string("–")) + " | " + (t.psnrDb ? fixed(*t.psnrDb, 2) : "ref") +
                  " | " + (t.psnrReflectionDb ? fixed(*t.psnrReflectionDb, 2) : "ref") + " | " +
                  (t.coverage ? fixed(*t.coverage, 4) : "ref") + " |\n";
        }
        md += "\n";
    }
    if (!r.reflectors.empty()) {
        md += "## Reflector count (" + r.reflectorsScene + ", camera " + r.reflectorsCamera + "): `ppr.project` ms\n\n";
        md += "| reflectors | tiles=1 | tiles=0 | tiles=0 / tiles=1 | tiles=1 / (N=1) | pairs kept (tiles=1) | pairs without culling |\n"
              "|---:|---:|---:|---:|---:|---:|---:|\n";
        const BenchReflectorRow* first = findRow(r, reflectorCounts(r).front(), true);
        for (uint32_t n : reflectorCounts(r)) {
            const BenchReflectorRow* on = findRow(r, n, true);
            const BenchReflectorRow* off = findRow(r, n, false);
            md += "| " + std::to_string(n) + " | " + (on ? fixed(on->projectMs, 2) : "–") + " | " + (off ? fixed(off->projectMs, 2) : "–") +
                  " | " + (on && off && on->projectMs > 0 ? fixed(off->projectMs / on->projectMs, 2) : "–") + " | " +
                  (on && first && first->projectMs > 0 ? fixed(on->projectMs / first->projectMs, 2) : "–") + " | " +
                  (on ? std::to_string(on->pairs) : "–") + " | " + (on ? std::to_string(on->pairsUnculled) : "–") + " |\n";
        }
        md += "\n";
    }
    if (!r.coverage.empty()) {
        md += "## Reflective screen fraction (" + r.coverageScene + "): `ppr.reflect` ms\n\n";
        md += "| camera | reflective tiles | indirect=1 (+ clear) | indirect=0 | indirect / whole screen |\n|---|---:|---:|---:|---:|\n";
        for (const std::string& cam : coverageCameras(r)) {
            const BenchCoverageRow* on = findRow(r, cam, true);
            const BenchCoverageRow* off = findRow(r, cam, false);
            const double onMs = on ? on->reflectMs + on->clearMs : 0.0;
            md += "| " + cam + " | " + (on ? fixed(on->reflectiveTiles * 100.0, 1) + " %" : "–") + " | " +
                  (on ? fixed(on->reflectMs, 2) + " (+ " + fixed(on->clearMs, 2) + ")" : "–") + " | " + (off ? fixed(off->reflectMs, 2) : "–") +
                  " | " + (on && off && off->reflectMs > 0 ? fixed(onMs / off->reflectMs, 2) : "–") + " |\n";
        }
        md += "\n";
    }
    return md;
}

bool writeBenchPlot(const BenchResults& r, const std::string& path) {
    std::vector<util::Rgba8Image> charts;
    if (!r.reflectors.empty()) {
        PlotSpec spec;
        spec.title = "ppr.project vs reflector count";
        spec.xLabel = "mirror tiles (reflectors)";
        spec.yLabel = "GPU ms";
        spec.logX = true;
        for (bool tiles : {true, false}) {
            PlotSeries s;
            s.name = tiles ? "tiles=1 (culling)" : "tiles=0 (all per pixel)";
            for (const BenchReflectorRow& row : r.reflectors)
                if (row.tiles == tiles) {
                    s.x.push_back(row.reflectors);
                    s.y.push_back(row.projectMs);
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
