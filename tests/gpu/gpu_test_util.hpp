#pragma once
// Helpers shared by the GPU tests: a validated context + default scene, image statistics, running
// the ppr executable.
#include "render/headless.hpp"
#include "cli/scene_source.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <string>

namespace ppr::test {

// Why this machine's device cannot run the `raytraced` reference ("" when it can; lavapipe can): its
// tests skip with that reason on a GPU driver without VK_KHR_ray_query instead of failing.
inline const std::string& rayQueryMissing() {
    static const std::string why = [] {
        vk::ContextOptions o;
        return vk::Context::create(o)->rayQueryUnavailableReason();
    }();
    return why;
}
#define PPR_SKIP_WITHOUT_RAY_QUERY()                                                            \
    do {                                                                                        \
        if (!::ppr::test::rayQueryMissing().empty()) GTEST_SKIP() << ::ppr::test::rayQueryMissing(); \
    } while (0)

struct GpuFixture {
    std::unique_ptr<vk::Context> ctx;
    scene::Scene scene;
    std::unique_ptr<app::Renderer> renderer;
    std::unique_ptr<app::HeadlessRenderer> headless;

    explicit GpuFixture(const std::string& scenePath = PPR_DEFAULT_SCENE_FILE) : GpuFixture(scene::loadGltf(scenePath)) {}
    explicit GpuFixture(scene::Scene s) : scene(std::move(s)) {
        vk::ContextOptions o;
        o.validation = true;  // Khronos validation + synchronization validation
        ctx = vk::Context::create(o);
        renderer = std::make_unique<app::Renderer>(*ctx, scene);
        headless = std::make_unique<app::HeadlessRenderer>(*ctx, *renderer);
    }
    scene::CameraPose camera(const std::string& name) const {
        const scene::NamedCamera* c = scene.findCamera(name);
        if (!c) throw std::runtime_error("test: no camera " + name);
        return c->pose;
    }
};

// The index of the scene's material called `name` (throws when there is none).
inline int materialNamed(const scene::Scene& s, const std::string& name) {
    for (size_t i = 0; i < s.materials.size(); ++i)
        if (s.materials[i].name == name) return int(i);
    throw std::runtime_error("test: no material " + name);
}

// Byte-for-byte equality of two images.
inline bool identical(const util::Rgba8Image& a, const util::Rgba8Image& b) {
    return a.width == b.width && a.height == b.height && a.pixels == b.pixels;
}

// Standard deviation of luma over the image (0..255).
inline double lumaStdDev(const util::Rgba8Image& img) {
    double sum = 0, sum2 = 0;
    const size_t n = size_t(img.width) * img.height;
    for (size_t i = 0; i < n; ++i) {
        const uint8_t* p = &img.pixels[i * 4];
        double y = 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
        sum += y;
        sum2 += y * y;
    }
    double mean = sum / n;
    return std::sqrt(std::max(0.0, sum2 / n - mean * mean));
}

struct RunResult {
    int exitCode = -1;
    std::string output;  // stdout + stderr
};

inline RunResult runPpr(const std::string& args) {
    std::string cmd = std::string(PPR_EXE) + " " + args + " 2>&1";
    RunResult r;
    FILE* pipe = popen(cmd.c_str(), "r");
    if (!pipe) return r;
    char buf[4096];
    while (size_t n = fread(buf, 1, sizeof(buf), pipe)) r.output.append(buf, n);
    int status = pclose(pipe);
    r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return r;
}

// Sets an environment variable for the scope, so that the ppr processes a test starts see it (e.g.
// PPR_HIDE_RAY_QUERY=1, a device without ray queries), then puts back what was there.
class ScopedEnv {
public:
    ScopedEnv(const char* name, const char* value) : name_(name) {
        if (const char* v = std::getenv(name)) before_ = v;
        setenv(name, value, 1);
    }
    ~ScopedEnv() {
        if (before_) setenv(name_, before_->c_str(), 1);
        else unsetenv(name_);
    }
    ScopedEnv(const ScopedEnv&) = delete;
    ScopedEnv& operator=(const ScopedEnv&) = delete;

private:
    const char* name_;
    std::optional<std::string> before_;
};

// A JSON file the ppr executable wrote (report.json, metrics.json).
inline nlohmann::json readJson(const std::filesystem::path& p) {
    std::ifstream f(p);
    return nlohmann::json::parse(f);
}

inline std::filesystem::path tempDir(const std::string& name) {
    auto dir = std::filesystem::temp_directory_path() / ("ppr-test-" + name + "-" + std::to_string(::getpid()));
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

}  // namespace ppr::test
