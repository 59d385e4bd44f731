#include "capture/capture.hpp"

#include "capture/report.hpp"
#include "render/headless_session.hpp"
#include "util/output_files.hpp"

#include <algorithm>
#include <cstdio>
#include <fstream>

namespace ppr::app {

int runCapture(const Options& o) {
    HeadlessSession s(o);
    // Several cameras: one sub-folder each plus a summary.
    nlohmann::json summary;
    summary["cameras"] = nlohmann::json::object();
    for (const ResolvedCamera& cam : s.cameras) {
        const std::filesystem::path dir = s.cameraDir(cam.name);
        const uint32_t errorsBefore = s.ctx->validationErrors();
        CaptureResult r = s.headless->capture(cam.pose, s.extent, s.frames, o.dumpGraph);
        if (!r.cullLog.empty()) std::fprintf(stderr, "%s", r.cullLog.c_str());
        if (!r.warning.empty()) std::fprintf(stderr, "ppr: warning: %s\n", r.warning.c_str());
        util::writePng((dir / "final.png").string(), r.image);
        ReportInfo info;
        info.scene = s.scene.sourcePath;
        info.camera = cam.name;
        info.pose = cam.pose;
        info.size = s.extent;
        info.technique = o.technique;
        info.reflectors = s.renderer->reflectors().size();
        info.reflectorsProjected = std::min<size_t>(info.reflectors, gpu::kPprMaxReflectors);
        info.settings = &s.headless->settings();
        info.validationEnabled = s.ctx->validationEnabled();
        info.validationErrors = s.ctx->validationErrors() - errorsBefore;
        info.images = {{"final", "final.png"}};
        if (o.dumpGraph) {
            util::writeTextFile(dir / "graph.dot", r.dot);
            info.images["graph"] = "graph.dot";
        }
        writeJsonFile((dir / "report.json").string(), makeReport(*s.ctx, info, r));
        summary["cameras"][cam.name] = {{"dir", dir.string()}, {"total_gpu_ms", r.totalMedianMs},
                                        {"validation_errors", info.validationErrors}};
        std::printf("ppr: %-10s %ux%u  %.2f ms GPU (median of %u frames)  -> %s\n", cam.name.c_str(), s.extent.width, s.extent.height,
                    r.totalMedianMs, r.medianFrames, (dir / "final.png").c_str());
    }
    if (!s.singleCamera()) {
        summary["device"] = s.ctx->info().name;
        summary["validation_errors"] = s.ctx->validationErrors();
        writeJsonFile((std::filesystem::path(o.out) / "summary.json").string(), summary);
    }
    return s.finish();
}

}  // namespace ppr::app
