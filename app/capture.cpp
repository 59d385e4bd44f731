#include "capture.hpp"

#include "headless.hpp"
#include "report.hpp"
#include "scene_source.hpp"

#include <cstdio>
#include <filesystem>
#include <fstream>

namespace ppr::app {

int runCapture(const Options& o) {
    const scene::Scene scene = loadScene(o);
    const std::vector<ResolvedCamera> cameras = resolveCameras(scene, o.camera);
    vk::ContextOptions co;
    co.validation = o.validation;
    auto ctx = vk::Context::create(co);
    std::printf("ppr: %s (%s, Vulkan %s)%s\n", ctx->info().name.c_str(), ctx->info().type.c_str(), ctx->info().apiVersionString.c_str(),
                ctx->validationEnabled() ? ", validation + synchronization validation on" : "");

    Renderer renderer(*ctx, scene);
    for (const std::string& kv : o.sets) renderer.settings().apply(kv);
    renderer.setTechnique(o.technique);
    HeadlessRenderer headless(*ctx, renderer);
    const VkExtent2D extent{o.width, o.height};
    const uint32_t frames = o.frames ? o.frames : 5;

    // One camera: files go straight into --out. Several: one sub-folder per camera + a summary.
    const bool single = cameras.size() == 1;
    nlohmann::json summary;
    summary["cameras"] = nlohmann::json::object();
    for (const ResolvedCamera& cam : cameras) {
        std::filesystem::path dir = single ? std::filesystem::path(o.out) : std::filesystem::path(o.out) / cam.name;
        std::filesystem::create_directories(dir);
        const uint32_t errorsBefore = ctx->validationErrors();
        CaptureResult r = headless.capture(cam.pose, extent, frames, o.dumpGraph);
        if (!r.cullLog.empty()) std::fprintf(stderr, "%s", r.cullLog.c_str());
        util::writePng((dir / "final.png").string(), r.image);
        ReportInfo info;
        info.scene = scene.sourcePath;
        info.camera = cam.name;
        info.pose = cam.pose;
        info.size = extent;
        info.technique = o.technique;
        info.reflectors = renderer.reflectors().size();
        info.settings = &renderer.settings();
        info.validationEnabled = ctx->validationEnabled();
        info.validationErrors = ctx->validationErrors() - errorsBefore;
        info.images = {{"final", "final.png"}};
        if (o.dumpGraph) {
            std::ofstream((dir / "graph.dot").string()) << r.dot;
            info.images["graph"] = "graph.dot";
        }
        nlohmann::json report = makeReport(*ctx, info, r);
        writeJsonFile((dir / "report.json").string(), report);
        summary["cameras"][cam.name] = {{"dir", dir.string()}, {"total_gpu_ms", r.totalMedianMs},
                                        {"validation_errors", info.validationErrors}};
        std::printf("ppr: %-10s %ux%u  %.2f ms GPU (median of %u frames)  -> %s\n", cam.name.c_str(), extent.width, extent.height,
                    r.totalMedianMs, frames, (dir / "final.png").c_str());
    }
    if (!single) {
        summary["device"] = ctx->info().name;
        summary["validation_errors"] = ctx->validationErrors();
        writeJsonFile((std::filesystem::path(o.out) / "summary.json").string(), summary);
    }
    if (ctx->validationErrors() > 0) {
        std::fprintf(stderr, "ppr: %u validation error(s)\n", ctx->validationErrors());
        return 1;
    }
    std::printf("ppr: wrote %s\n", std::filesystem::absolute(o.out).c_str());
    return 0;
}

}  // namespace ppr::app
