#include "bench/bench.hpp"

#include "bench/bench_report.hpp"
#include "capture/report.hpp"
#include "cli/scene_source.hpp"
#include "metrics/compare_metrics.hpp"
#include "metrics/median.hpp"
#include "render/headless.hpp"
#include "scene/stress_scene.hpp"
#include "techniques/technique_table.hpp"
#include "util/output_files.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <set>
#include <stdexcept>

namespace ppr::app {
namespace {

constexpr uint32_t kSweepReflectorCounts[] = {1, 4, 16, 64, 256, 1024};
constexpr uint32_t kCoverageSceneTiles = 256;
const char* const kCoverageCameras[] = {"reflective_5", "reflective_25", "reflective_100"};

// One line on stderr rewritten in place on a terminal (one line per step otherwise, for logs).
class Progress {
public:
    explicit Progress(uint32_t steps) : steps_(steps), tty_(isatty(STDERR_FILENO) != 0) {}
    void step(const std::string& label) {
        ++step_;
        label_ = label;
        if (!tty_) std::fprintf(stderr, "ppr bench [%u/%u] %s\n", step_, steps_, label_.c_str());
    }
    void frame(uint32_t f, uint32_t frames) {
        if (tty_) std::fprintf(stderr, "\r\033[Kppr bench [%u/%u] %s: frame %u/%u", step_, steps_, label_.c_str(), f, frames);
    }
    void done() {
        if (tty_) std::fprintf(stderr, "\r\033[K");
    }
    // Steps counted at the start that will not run (a skipped technique's later rounds).
    void drop(uint32_t steps) { steps_ -= std::min(steps, steps_); }

private:
    uint32_t steps_, step_ = 0;
    bool tty_;
    std::string label_;
};

// A scene with its renderer; members in teardown order (reverse of declaration).
struct Rig {
    Rig(const vk::Context& ctx, scene::Scene s, const Options& o) : scene(std::move(s)) {
        renderer = std::make_unique<Renderer>(ctx, scene);
        headless = std::make_unique<HeadlessRenderer>(ctx, *renderer);
        for (const std::string& kv : o.sets) headless->settings().apply(kv);
    }
    scene::CameraPose camera(const std::string& name) const {
        return resolveCameras(scene, name).front().pose;  // throws naming the camera when missing
    }
    scene::Scene scene;
    std::unique_ptr<Renderer> renderer;
    std::unique_ptr<HeadlessRenderer> headless;
};

struct Measured {
    std::map<std::string, double> passMs;  // with rounds: the median per pass over them
    double frameMs = 0.0;
    CaptureResult last;  // the last frame (image, reflection when asked, counters)
    std::vector<std::map<std::string, double>> roundPassMs;  // each round's per-pass medians (--rounds)
    std::vector<double> roundFrameMs;

    // Adds a round's measurement: its last frame replaces the one kept.
    void addRound(Measured round) {
        roundPassMs.push_back(std::move(round.passMs));
        roundFrameMs.push_back(round.frameMs);
        last = std::move(round.last);
        passMs = medianPerPass(roundPassMs);
        frameMs = median(roundFrameMs);
    }
    // The round-th round's time of one pass (0 when it did not run).
    double roundPass(size_t round, const std::string& name) const {
        const auto it = roundPassMs[round].find(name);
        return it == roundPassMs[round].end() ? 0.0 : it->second;
    }
};

double passOr0(const std::map<std::string, double>& m, const std::string& name) {
    auto it = m.find(name);
    return it == m.end() ? 0.0 : it->second;
}

class Bench {
public:
    explicit Bench(const Options& o) : o_(o), extent_{o.width, o.height}, frames_(o.frames ? o.frames : 10) {
        for (const std::string& kv : o.sets) settings_.apply(kv);
        util::prepareOutputDirectory(o.out, "--out " + o.out);  // before the run, not after it
        vk::ContextOptions co;
        co.validation = o.validation;
        ctx_ = vk::Context::create(co);
        std::printf("ppr: %s (%s, Vulkan %s)%s\n", ctx_->info().name.c_str(), ctx_->info().type.c_str(),
                    ctx_->info().apiVersionString.c_str(), ctx_->validationEnabled() ? ", validation + synchronization validation on" : "");
    }

    int run() {
        const bool techniques = wants("techniques"), reflectors = wants("reflectors"), coverage = wants("coverage");
        uint32_t steps = 0;
        if (techniques) steps += static_cast<uint32_t>(techniqueList().size()) + (hasPlanar() ? 0 : 1);
        if (reflectors) steps += 2 * static_cast<uint32_t>(std::size(kSweepReflectorCounts));
        if (coverage) steps += 2 * static_cast<uint32_t>(std::size(kCoverageCameras));
        progress_ = std::make_unique<Progress>(steps * o_.rounds);
        if (techniques) runTechniques();
        if (reflectors) runReflectors();
        if (coverage) runCoverage();
        progress_->done();
        return write();
    }

private:
    bool wants(const std::string& sweep) const { return std::find(o_.sweeps.begin(), o_.sweeps.end(), sweep) != o_.sweeps.end(); }
    // The --technique ones (each once), else every technique but `none` (which costs nothing).
    std::vector<std::string> techniqueList() const {
        const bool all = o_.techniques.empty();
        std::vector<std::string> list;
        for (const std::string& t : all ? techniqueNames() : o_.techniques)
            if (!(all && t == "none") && std::find(list.begin(), list.end(), t) == list.end()) list.push_back(t);
        return list;
    }
    bool hasPlanar() const {
        const auto list = techniqueList();
        return std::find(list.begin(), list.end(), "planar") != list.end();
    }

    Measured measure(Rig& rig, const scene::CameraPose& camera, bool readReflection) {
        Measured m;
        if (o_.warmup > 0) rig.headless->capture(camera, extent_, o_.warmup);
        std::map<std::string, std::vector<double>> perPass;
        std::vector<double> totals;
        for (uint32_t f = 0; f < frames_; ++f) {
            progress_->frame(f + 1, frames_);
            m.last = rig.headless->capture(camera, extent_, 1, false, readReflection && f + 1 == frames_);
            for (const auto& [name, ms] : m.last.passMedianMs) perPass[name].push_back(ms);
            totals.push_back(m.last.totalMedianMs);
        }
        for (auto& [name, values] : perPass) m.passMs[name] = median(values);
        m.frameMs = median(totals);
        if (!m.last.warning.empty() && warned_.insert(m.last.warning).second)
            std::fprintf(stderr, "\nppr: warning: %s\n", m.last.warning.c_str());
        return m;
    }

    void runTechniques() {
        Rig rig(*ctx_, loadScene(o_), o_);
        const ResolvedCamera cam = resolveCameras(rig.scene, o_.camera).front();
        results_.techniquesCamera = cam.name;
        // A technique this device cannot run (raytraced without ray queries): named on the command line it
        // is an error, as in capture; in the default list it is skipped and said so.
        std::vector<std::string> rows;
        for (const std::string& t : techniqueList()) {
            const std::string why = rig.renderer->unsupported(parseTechniqueVariant(t).name, extent_);
            if (why.empty()) {
                rows.push_back(t);
                continue;
            }
            if (!o_.techniques.empty()) throw std::runtime_error("--technique " + t + ": " + why);
            progress_->step("technique " + t + ": skipped");
            progress_->drop(o_.rounds - 1);  // said once, not once per round
            std::fprintf(stderr, "ppr: bench: skipping %s: %s\n", t.c_str(), why.c_str());
            results_.skippedTechniques[t] = why;
        }
        std::vector<std::string> list = rows;
        if (!hasPlanar()) list.insert(list.begin(), "planar");  // the reference, not listed
        const float exposure = rig.headless->settings().values().view.exposure;
        std::map<std::string, Measured> measured;
        for (uint32_t round = 0; round < o_.rounds; ++round)
            for (const std::string& t : list) {
                progress_->step("technique " + t + " on " + cam.name + roundLabel(round));
                const Settings shared = rig.headless->setVariant(t);
                measured[t].addRound(measure(rig, cam.pose, round + 1 == o_.rounds));  // the images of the last round
                rig.headless->settings() = shared;
            }
        const Measured& reference = measured.at("planar");
        for (const std::string& t : rows) {
            const Measured& m = measured.at(t);
            BenchTechnique row;
            row.name = t;
            row.passMs = m.passMs;
            row.passOrder = m.last.passOrder;
            if (o_.rounds > 1) row.roundPassMs = m.roundPassMs;
            row.frameMs = m.frameMs;
            const std::string name = parseTechniqueVariant(t).name;
            row.techniqueMs = techniqueCost(name, m.passMs);
            for (const auto& [pass, ms] : m.passMs)
                if (isTechniquePass(name, pass)) row.costPasses.insert(pass);
            if (t != "planar") {
                FloatImage reflection = m.last.reflection;
                if (reflection.rgba.empty()) {  // no reflection image (none): no reflection anywhere
                    reflection.width = extent_.width;
                    reflection.height = extent_.height;
                    reflection.rgba.assign(size_t(extent_.width) * extent_.height * 4, 0.0f);
                }
                const ReflectionScore s = scoreReflection(reflection, reference.last.reflection, exposure);
                row.psnrDb = compositedPsnrDb(m.last.image, reference.last.image, reference.last.reflection);
                row.psnrReflectionDb = s.psnrDb;
                row.coverage = s.coverage;
            }
            results_.techniques.push_back(row);
        }
    }

    void runReflectors() {
        results_.reflectorsScene = "stress:N";
        results_.reflectorsCamera = "overview";
        std::map<std::pair<uint32_t, bool>, Measured> measured;  // (reflectors, tiles)
        for (uint32_t round = 0; round < o_.rounds; ++round)
            for (uint32_t n : kSweepReflectorCounts) {
                Rig rig(*ctx_, scene::makeStressScene(n), o_);
                rig.headless->setTechnique("ppr");
                const scene::CameraPose camera = rig.camera("overview");
                for (bool tiles : {true, false}) {
                    progress_->step("reflectors N=" + std::to_string(n) + " tiles=" + (tiles ? "1" : "0") + roundLabel(round));
                    rig.headless->settings().set("tiles", tiles ? "1" : "0");
                    measured[{n, tiles}].addRound(measure(rig, camera, false));
                }
            }
        for (uint32_t n : kSweepReflectorCounts)
            for (bool tiles : {true, false}) {
                const Measured& m = measured.at({n, tiles});
                BenchReflectorRow row;
                row.reflectors = n;
                row.tiles = tiles;
                row.projectMs = passOr0(m.passMs, "ppr.project");
                row.boundsMs = passOr0(m.passMs, "ppr.bounds");
                row.reachMs = passOr0(m.passMs, "ppr.reach");
                row.techniqueMs = techniqueCost("ppr", m.passMs);
                for (size_t round = 0; o_.rounds > 1 && round < m.roundPassMs.size(); ++round) {
                    row.roundProjectMs.push_back(m.roundPass(round, "ppr.project"));
                    row.roundReachMs.push_back(m.roundPass(round, "ppr.reach"));
                }
                if (m.last.pprStats) {
                    row.pairs = m.last.pprStats->reflectorTilePairs;
                    row.pairsUnculled = uint64_t(m.last.pprStats->tilesWithContent) * std::min(n, gpu::kPprMaxReflectors);
                }
                results_.reflectors.push_back(row);
            }
    }

    void runCoverage() {
        results_.coverageScene = "stress:" + std::to_string(kCoverageSceneTiles);
        Rig rig(*ctx_, scene::makeStressScene(kCoverageSceneTiles), o_);
        rig.headless->setTechnique("ppr");
        const uint32_t tiles = gpu::pprTilesCovering(extent_.width) * gpu::pprTilesCovering(extent_.height);
        std::map<std::pair<std::string, bool>, Measured> measured;  // (camera, indirect)
        for (uint32_t round = 0; round < o_.rounds; ++round)
            for (const char* name : kCoverageCameras) {
                const scene::CameraPose camera = rig.camera(name);
                for (bool indirect : {true, false}) {
                    progress_->step(std::string("coverage ") + name + " indirect=" + (indirect ? "1" : "0") + roundLabel(round));
                    rig.headless->settings().set("indirect", indirect ? "1" : "0");
                    measured[{name, indirect}].addRound(measure(rig, camera, false));
                }
            }
        for (const char* name : kCoverageCameras)
            for (bool indirect : {true, false}) {
                const Measured& m = measured.at({name, indirect});
                BenchCoverageRow row;
                row.camera = name;
                row.indirect = indirect;
                row.reflectMs = passOr0(m.passMs, "ppr.reflect");
                row.clearMs = passOr0(m.passMs, "ppr.reflection.clear");
                row.classifyMs = passOr0(m.passMs, "tiles.classify");
                for (size_t round = 0; o_.rounds > 1 && round < m.roundPassMs.size(); ++round) {
                    row.roundReflectMs.push_back(m.roundPass(round, "ppr.reflect"));
                    row.roundClearMs.push_back(m.roundPass(round, "ppr.reflection.clear"));
                }
                if (m.last.pprStats) row.reflectiveTiles = double(m.last.pprStats->dispatch[gpu::kTileClassPlanar].x) / tiles;
                results_.coverage.push_back(row);
            }
    }

    // " (round r/N)" in the progress line when there are rounds.
    std::string roundLabel(uint32_t round) const {
        return o_.rounds > 1 ? " (round " + std::to_string(round + 1) + "/" + std::to_string(o_.rounds) + ")" : "";
    }

    std::string commandLine() const {
        std::string c = "ppr bench --size " + std::to_string(extent_.width) + "x" + std::to_string(extent_.height) + " --frames " +
                        std::to_string(frames_) + " --warmup " + std::to_string(o_.warmup);
        if (o_.rounds > 1) c += " --rounds " + std::to_string(o_.rounds);
        if (o_.sweeps != benchSweepNames())
            for (const std::string& s : o_.sweeps) c += " --sweep " + s;
        if (!o_.scene.empty()) c += " --scene " + o_.scene;
        if (!o_.camera.empty()) c += " --camera " + o_.camera;
        for (const std::string& t : o_.techniques) c += " --technique " + t;
        for (const std::string& kv : o_.sets) c += " --set " + kv;
        return c;
    }

    int write() {
        const char* threads = std::getenv("LP_NUM_THREADS");
        const char* cache = std::getenv("MESA_SHADER_CACHE_DISABLE");
        results_.header = {{"device", ctx_->info().name},
                           {"device_type", ctx_->info().type},
                           {"driver", ctx_->info().driver},
                           {"api_version", ctx_->info().apiVersionString},
                           {"size", {extent_.width, extent_.height}},
                           {"frames", frames_},
                           {"warmup", o_.warmup},
                           {"rounds", o_.rounds},
                           {"command", commandLine()},
                           {"environment",
                            {{"LP_NUM_THREADS", threads ? threads : ""}, {"MESA_SHADER_CACHE_DISABLE", cache ? cache : ""}}},
                           {"settings", settings_.canonicalTexts()},
                           {"validation_errors", ctx_->validationErrors()}};
        const std::filesystem::path out(o_.out);
        util::prepareOutputDirectory(out, "--out " + o_.out);
        writeJsonFile((out / "bench.json").string(), benchJson(results_));
        util::writeTextFile(out / "bench.md", benchMarkdown(results_, commandLine()));
        if (writeBenchPlot(results_, (out / "bench.png").string())) std::printf("ppr: plot %s\n", (out / "bench.png").c_str());
        std::printf("ppr: wrote %s (bench.json, bench.md)\n", std::filesystem::absolute(out).c_str());
        if (ctx_->validationErrors() > 0) {
            std::fprintf(stderr, "ppr: %u validation error(s)\n", ctx_->validationErrors());
            return 1;
        }
        return 0;
    }

    const Options& o_;
    VkExtent2D extent_;
    uint32_t frames_;
    std::unique_ptr<vk::Context> ctx_;
    std::unique_ptr<Progress> progress_;
    std::set<std::string> warned_;
    Settings settings_;  // the --set values every rig starts from (bench.json "settings")
    BenchResults results_;
};

}  // namespace

int runBench(const Options& o) { return Bench(o).run(); }

}  // namespace ppr::app
