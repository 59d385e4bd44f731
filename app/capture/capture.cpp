#include "capture/capture.hpp"

#include "capture/report.hpp"
#include "render/headless_session.hpp"
#include "scene/camera_path.hpp"
#include "util/output_files.hpp"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <sstream>

namespace ppr::app {
namespace {

// --path: one shot along the path, every frame read back (frames/frame_NNN.png) with its pose and GPU
// time in frames.csv; returns the last frame's result (its report and final.png).
CaptureResult capturePath(HeadlessSession& s, const ResolvedCamera& cam, const std::filesystem::path& dir) {
    const std::vector<scene::CameraPose> poses = s.path(cam);
    util::prepareOutputDirectory(dir / "frames", "--out " + s.options.out);
    std::ostringstream csv;
    csv << "frame,x,y,z,yaw_deg,pitch_deg,frame_gpu_ms\n";
    CaptureResult r;
    for (size_t i = 0; i < poses.size(); ++i) {
        s.headless->setSceneTime(scene::cameraPathSceneTime(s.options.path, uint32_t(i)));
        r = s.headless->capture(poses[i], s.extent, 1, false, false, i == 0);
        char name[32];
        std::snprintf(name, sizeof name, "frame_%03zu.png", i);
        util::writePng((dir / "frames" / name).string(), r.image);
        const scene::CameraPose& p = poses[i];
        csv << i << ',' << p.position.x << ',' << p.position.y << ',' << p.position.z << ',' << p.yawDeg << ',' << p.pitchDeg << ','
            << r.totalMedianMs << '\n';
    }
    util::writeTextFile(dir / "frames.csv", csv.str());
    r.frames = static_cast<uint32_t>(poses.size());
    return r;
}

}  // namespace

int runCapture(const Options& o) {
    HeadlessSession s(o);
    // Several cameras: one sub-folder each plus a summary.
    nlohmann::json summary;
    summary["cameras"] = nlohmann::json::object();
    for (const ResolvedCamera& cam : s.cameras) {
        const std::filesystem::path dir = s.cameraDir(cam.name);
        const uint32_t errorsBefore = s.ctx->validationErrors();
        CaptureResult r = o.path.empty() ? s.headless->capture(cam.pose, s.extent, s.frames, o.dumpGraph) : capturePath(s, cam, dir);
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
        if (!o.path.empty()) info.images.insert({{"frames", "frames"}, {"frames_csv", "frames.csv"}});
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
