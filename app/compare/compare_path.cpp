// `ppr compare --path`: TAA and the techniques under camera motion. Per frame of the path the
// reference technique is rendered 16 times with Halton jitter and the images averaged (the
// supersampled reference, TAA off), and once more unjittered for its reflector pixels (which of them
// are compare's scored pixels, the reflected point on screen and unoccluded, and which are not). Then each
// --technique row renders the whole path as one shot (its TAA history carries from frame to frame)
// and every frame is scored against that frame's reference.
#include "compare/compare.hpp"

#include "bench/bench_plot.hpp"
#include "capture/report.hpp"
#include "metrics/compare_metrics.hpp"
#include "metrics/contact_sheet.hpp"
#include "metrics/median.hpp"
#include "metrics/temporal_metrics.hpp"
#include "render/headless_session.hpp"
#include "scene/camera_path.hpp"
#include "util/output_files.hpp"

#include <cstdio>
#include <sstream>

namespace ppr::app {
namespace {

struct ReferenceFrame {
    util::Rgba8Image supersampled;
    // The unjittered reference's reflection: its alpha is kReflectionHit at compare's scored pixels
    // (compositedPsnrDb's mask); allReflectorPixels of it marks every reflector pixel.
    FloatImage reflection;
};

std::string frameFile(const std::string& folder, size_t frame) {
    char name[32];
    std::snprintf(name, sizeof name, "/frame_%03zu.png", frame);
    return folder + name;
}

// A row's name short enough for a tile's label: "planar@taa=1,reproject=virtual" → "planar virtual".
std::string stripName(std::string t) {
    for (const std::string& cut : {std::string("taa=1,reproject="), std::string("reproject=")})
        if (const size_t at = t.find(cut); at != std::string::npos) t.erase(at, cut.size());
    for (char& c : t)
        if (c == '@' || c == ',') c = ' ';
    return t;
}

}  // namespace

int runComparePath(const Options& o) {
    HeadlessSession session(o);
    const vk::Context& ctx = *session.ctx;
    HeadlessRenderer& headless = *session.headless;
    const VkExtent2D extent = session.extent;
    nlohmann::json summary;
    summary["cameras"] = nlohmann::json::object();
    for (const ResolvedCamera& cam : session.cameras) {
        const std::filesystem::path dir = session.cameraDir(cam.name);
        const uint32_t errorsBefore = ctx.validationErrors();
        const std::vector<scene::CameraPose> poses = session.path(cam);
        // A still camera; on a moving scene its flicker is the change the reference does not make.
        const bool still = scene::isStill(poses);

        std::vector<ReferenceFrame> reference(poses.size());
        {
            const Settings shared = headless.settings();
            headless.setTechnique(o.reference);
            headless.settings().set("taa", "0");
            for (size_t i = 0; i < poses.size(); ++i) {
                headless.setSceneTime(scene::cameraPathSceneTime(o.path, uint32_t(i)));
                reference[i].supersampled = headless.captureSupersampled(poses[i], extent, scene::kJitterLength);
                reference[i].reflection = headless.capture(poses[i], extent, 1, false, true).reflection;
            }
            headless.settings() = shared;
        }
        util::prepareOutputDirectory(dir / "reference", "--out " + o.out);
        util::writePng(frameFile((dir / "reference").string(), poses.size() - 1), reference.back().supersampled);

        nlohmann::json metrics;
        metrics["camera"] = cam.name;
        metrics["path"] = o.path;
        metrics["size"] = {extent.width, extent.height};
        metrics["device"] = ctx.info().name;
        metrics["settings"] = headless.settings().canonicalTexts();
        metrics["frames"] = poses.size();
        metrics["still"] = still;
        metrics["reference"] = o.reference;
        metrics["reference_samples"] = scene::kJitterLength;
        metrics["techniques"] = nlohmann::json::object();
        std::ostringstream csv;
        csv << "technique,frame,x,y,z,yaw_deg,pitch_deg,psnr_db,reflector_psnr_db,change,excess_change,frame_gpu_ms,scored_psnr_db\n";
        PlotSpec whole{"whole frame vs " + std::to_string(scene::kJitterLength) + "x supersampled " + o.reference, "frame", "PSNR (dB)"};
        PlotSpec reflectors{"reflector pixels", "frame", "PSNR (dB)"};
        // strip.png: per row the middle and the last frame, each beside its error on reflector pixels.
        const size_t stripFrames[] = {poses.size() / 2, poses.size() - 1};
        std::vector<ContactTile> strip;
        for (const std::string& t : o.techniques) {
            const Settings shared = headless.setVariant(t);
            const std::string folder = (dir / ("frames_" + variantFileName(t))).string();
            util::prepareOutputDirectory(folder, "--out " + o.out);
            std::vector<TemporalFrame> frames;
            std::vector<double> frameMs;
            util::Rgba8Image previous;
            PlotSeries wholeSeries{t, {}, {}}, reflectorSeries{t, {}, {}};
            for (size_t i = 0; i < poses.size(); ++i) {
                headless.setSceneTime(scene::cameraPathSceneTime(o.path, uint32_t(i)));
                const CaptureResult r = headless.capture(poses[i], extent, 1, false, false, i == 0);
                const FloatImage reflectorPixels = allReflectorPixels(reference[i].reflection);
                TemporalFrame f;
                f.psnrDb = imagePsnrDb(r.image, reference[i].supersampled);
                f.reflectorPsnrDb = compositedPsnrDb(r.image, reference[i].supersampled, reflectorPixels);
                f.scoredPsnrDb = compositedPsnrDb(r.image, reference[i].supersampled, reference[i].reflection);
                f.change = i ? meanAbsoluteChange(r.image, previous) : 0.0;
                f.excessChange = i ? meanAbsoluteExcessChange(r.image, previous, reference[i].supersampled, reference[i - 1].supersampled) : 0.0;
                frames.push_back(f);
                frameMs.push_back(r.totalMedianMs);
                util::writePng(frameFile(folder, i), r.image);
                if (i == stripFrames[0] || i == stripFrames[1]) {
                    char label[64];
                    std::snprintf(label, sizeof label, " f%zu %.1f dB", i, f.reflectorPsnrDb);
                    strip.push_back({stripName(t) + label, r.image});
                    strip.push_back({"error (white = 0.25)", displayErrorHeatMap(r.image, reference[i].supersampled, reflectorPixels)});
                }
                const scene::CameraPose& p = poses[i];
                csv << '"' << t << "\"," << i << ',' << p.position.x << ',' << p.position.y << ',' << p.position.z << ',' << p.yawDeg << ','
                    << p.pitchDeg << ',' << f.psnrDb << ',' << f.reflectorPsnrDb << ',' << f.change << ',' << f.excessChange << ',' << r.totalMedianMs << ',' << f.scoredPsnrDb << '\n';
                wholeSeries.x.push_back(double(i));
                wholeSeries.y.push_back(std::min(f.psnrDb, 60.0));
                reflectorSeries.x.push_back(double(i));
                reflectorSeries.y.push_back(std::min(f.reflectorPsnrDb, 60.0));
                previous = r.image;
            }
            headless.settings() = shared;
            const TemporalSummary s = summarizeTemporal(frames, still, scene::kJitterLength);
            const nlohmann::json temporal = {{"psnr_db_mean", s.psnrDbMean},
                                             {"reflector_psnr_db_mean", s.reflectorPsnrDbMean},
                                             {"scored_psnr_db_mean", s.scoredPsnrDbMean},
                                             {"flicker", s.flicker ? nlohmann::json(*s.flicker) : nlohmann::json(nullptr)},
                                             {"frames", s.frames}};
            metrics["techniques"][t] = {{"temporal", temporal}, {"frame_gpu_ms", median(frameMs)}, {"frames_dir", "frames_" + variantFileName(t)}};
            if (still) metrics["techniques"][t]["flicker_from_frame"] = s.settledFrom;
            summary["cameras"][cam.name][t] = {{"temporal", temporal}};
            whole.series.push_back(wholeSeries);
            reflectors.series.push_back(reflectorSeries);
            std::printf("ppr: %-8s %-14s %s, %u frames: PSNR %6.2f dB mean, reflector pixels %6.2f dB mean, scored pixels %6.2f dB mean",
                        cam.name.c_str(), t.c_str(), o.path.c_str(), s.frames, s.psnrDbMean, s.reflectorPsnrDbMean, s.scoredPsnrDbMean);
            if (s.flicker) std::printf(", flicker %.3f levels", *s.flicker);
            std::printf("\n");
        }
        util::writeTextFile(dir / "temporal.csv", csv.str());
        util::writePng((dir / "strip.png").string(), makeContactSheet(strip, 4));
        // As tall as the longer legend needs (one row per technique variant), the two side by side.
        const uint32_t plotHeight = std::max(plotHeightFor(whole, 640, 400, 200), plotHeightFor(reflectors, 640, 400, 200));
        util::writePng((dir / "temporal.png").string(),
                       sideBySide({renderPlot(whole, 640, plotHeight), renderPlot(reflectors, 640, plotHeight)}));
        metrics["images"] = {{"plot", "temporal.png"}, {"csv", "temporal.csv"}, {"strip", "strip.png"}, {"reference_last_frame", "reference/" + frameFile("", poses.size() - 1).substr(1)}};
        metrics["validation"] = ctx.validationEnabled();
        metrics["validation_errors"] = ctx.validationErrors() - errorsBefore;
        writeJsonFile((dir / "metrics.json").string(), metrics);
        std::printf("ppr: %-8s -> %s\n", cam.name.c_str(), (dir / "temporal.png").c_str());
    }
    if (!session.singleCamera()) {
        summary["validation_errors"] = ctx.validationErrors();
        writeJsonFile((std::filesystem::path(o.out) / "metrics.json").string(), summary);
    }
    return session.finish();
}

}  // namespace ppr::app
