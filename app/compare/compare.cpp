#include "compare/compare.hpp"

#include "common/reflection.h"
#include "capture/report.hpp"
#include "metrics/contact_sheet.hpp"
#include "metrics/error_breakdown.hpp"
#include "metrics/fixed_text.hpp"
#include "render/headless_session.hpp"

#include <cstdio>
#include <filesystem>

namespace ppr::app {
namespace {

// White where the reference scores pixels, grey where a reflector's reflected point is off screen or
// occluded, the reference's final image dimmed elsewhere.
util::Rgba8Image scoredPixelsImage(const FloatImage& reference, const util::Rgba8Image& context) {
    util::Rgba8Image out = context;
    for (size_t i = 0; i < size_t(reference.width) * reference.height; ++i) {
        const float a = reference.rgba[i * 4 + 3];
        uint8_t* p = &out.pixels[i * 4];
        if (a == gpu::kReflectionHit) p[0] = p[1] = p[2] = 255;
        else if (a > 0.0f) p[0] = p[1] = p[2] = 96;
        else for (int c = 0; c < 3; ++c) p[c] = static_cast<uint8_t>(p[c] / 4);
    }
    return out;
}

// Glass panels, scored in their reflection atlas against the reference's (same layout: same camera,
// size and settings); empty when the reference has no glass reflection in view. A technique without
// one (screen-space techniques cannot reflect in transparent surfaces) scores as black.
nlohmann::json glassScores(const CaptureResult& r, const CaptureResult& ref, VkExtent2D extent, float exposure) {
    if (!ref.glass || ref.glassReflection.rgba.empty()) return nlohmann::json::object();
    FloatImage atlas = r.glassReflection;
    // A row with its own glass_atlas has another layout than the reference's: not comparable texel
    // for texel, so it is said instead of scored (the reference is rendered once per camera).
    if (!atlas.rgba.empty() && (atlas.width != ref.glassReflection.width || atlas.height != ref.glassReflection.height))
        return {{"glass_unscored", "its glass atlas is " + std::to_string(atlas.width) + "x" + std::to_string(atlas.height) +
                                       ", the reference's " + std::to_string(ref.glassReflection.width) + "x" +
                                       std::to_string(ref.glassReflection.height)}};
    if (atlas.rgba.empty()) {
        atlas.width = ref.glassReflection.width;
        atlas.height = ref.glassReflection.height;
        atlas.rgba.assign(ref.glassReflection.rgba.size(), 0.0f);
    }
    const ReflectionScore s = scoreReflection(atlas, ref.glassReflection, exposure);
    const FloatImage mask = glassScreenMask(ref.glassReflection, ref.glass->layout, extent.width, extent.height);
    return {{"psnr_db_glass", compositedPsnrDb(r.image, ref.image, mask)},
            {"psnr_reflection_db_glass", s.psnrDb},
            {"coverage_glass", s.coverage},
            {"scored_texels_glass", s.maskPixels}};
}

FloatImage emptyReflection(VkExtent2D extent) {  // technique `none`: no reflection anywhere
    FloatImage f;
    f.width = extent.width;
    f.height = extent.height;
    f.rgba.assign(size_t(extent.width) * extent.height * 4, 0.0f);
    return f;
}

// metrics.json's error_share_worst_* and error_classes (metrics/error_breakdown.hpp).
nlohmann::json breakdownJson(const ErrorBreakdown& b) {
    nlohmann::json classes = nlohmann::json::object();
    for (size_t c = 0; c < kErrorClassCount; ++c)
        classes[errorClassName(static_cast<ErrorClass>(c))] = {{"pixels", b.pixels[c]}, {"share", b.share[c]}};
    return {{"error_share_worst_1pct", b.worst1PercentShare},
            {"error_share_worst_10pct", b.worst10PercentShare},
            {"error_classes", classes},
            {"error_classes_geometric", b.pathKnown}};
}

}  // namespace

std::string variantFileName(std::string t) {
    for (char& c : t)
        if (c == '@' || c == ',') c = '_';
        else if (c == '=') c = '-';
    return t;
}

int runCompare(const Options& o) {
    if (!o.path.empty()) return runComparePath(o);
    HeadlessSession session(o);
    const vk::Context& ctx = *session.ctx;
    HeadlessRenderer& headless = *session.headless;
    const VkExtent2D extent = session.extent;
    const uint32_t frames = session.frames;
    const float exposure = headless.settings().values().view.exposure;

    nlohmann::json summary;
    summary["device"] = ctx.info().name;
    summary["size"] = {extent.width, extent.height};
    summary["techniques"] = o.techniques;
    summary["reference"] = o.reference;
    const std::string& truth = o.reference;
    // The screen-reachable score is the primary figure; a reference that knows every reflector pixel
    // (raytraced: also off screen and hidden) adds the *_all figures over all of them.
    const bool scoresAll = truth != "planar";
    summary["cameras"] = nlohmann::json::object();
    for (const ResolvedCamera& cam : session.cameras) {
        const std::filesystem::path dir = session.cameraDir(cam.name);
        const uint32_t errorsBefore = ctx.validationErrors();

        headless.setTechnique(truth);
        const CaptureResult ref = headless.capture(cam.pose, extent, frames, false, true);
        const std::string refFinal = "final_" + truth + ".png", refReflection = "reflection_" + truth + ".png";
        util::writePng((dir / refFinal).string(), ref.image);
        util::writePng((dir / refReflection).string(), reflectionDisplayImage(ref.reflection, exposure));
        const FloatImage allPixels = scoresAll ? allReflectorPixels(ref.reflection) : FloatImage{};

        nlohmann::json metrics;
        metrics["camera"] = cam.name;
        metrics["size"] = {extent.width, extent.height};
        metrics["device"] = ctx.info().name;
        metrics["settings"] = headless.settings().canonicalTexts();
        metrics["frames"] = frames;
        metrics["reference"] = truth;
        metrics["reference_run"] = {{"technique", truth},
                                    {"gpu_ms", techniqueMs(truth, ref)},
                                    {"frame_gpu_ms", ref.totalMedianMs},
                                    {"images", {{"final", refFinal}, {"reflection", refReflection}, {"scored_pixels", "scored_pixels.png"}, {"error_classes", "error_classes.png"}}}};
        metrics["techniques"] = nlohmann::json::object();
        std::vector<ContactTile> finals, reflections, errors;
        for (const std::string& t : o.techniques) {
            const Settings shared = headless.setVariant(t);
            const CaptureResult r = headless.capture(cam.pose, extent, frames, false, true);
            headless.settings() = shared;
            if (!r.warning.empty()) std::fprintf(stderr, "ppr: warning: %s\n", r.warning.c_str());
            const FloatImage reflection = r.reflection.rgba.empty() ? emptyReflection(extent) : r.reflection;
            const ReflectionScore s = scoreReflection(reflection, ref.reflection, exposure);
            const double psnr = compositedPsnrDb(r.image, ref.image, ref.reflection);
            const double ms = techniqueMs(headless.technique(), r);
            const std::string finalFile = "final_" + variantFileName(t) + ".png", reflFile = "reflection_" + variantFileName(t) + ".png",
                              errFile = "error_" + variantFileName(t) + ".png";
            const util::Rgba8Image heat = errorHeatMap(reflection, ref.reflection, exposure, r.image);
            util::writePng((dir / finalFile).string(), r.image);
            util::writePng((dir / reflFile).string(), reflectionDisplayImage(reflection, exposure));
            util::writePng((dir / errFile).string(), heat);
            const nlohmann::json glass = glassScores(r, ref, extent, exposure);
            const ErrorBreakdown breakdown = breakdownErrors(r.image, ref.image, r.reflection, ref.reflection, ref.reflectedPath);
            metrics["techniques"][t] = {{"psnr_db", psnr},
                                        {"psnr_reflection_db", s.psnrDb},
                                        {"coverage", s.coverage},
                                        {"gpu_ms", ms},
                                        {"frame_gpu_ms", r.totalMedianMs},
                                        {"mse_reflection", s.mse},
                                        {"scored_pixels", s.maskPixels},
                                        {"covered_pixels", s.coveredPixels},
                                        {"images", {{"final", finalFile}, {"reflection", reflFile}, {"error", errFile}}}};
            metrics["techniques"][t].update(breakdownJson(breakdown));
            metrics["techniques"][t].update(glass);
            summary["cameras"][cam.name][t] = {{"psnr_db", psnr},
                                               {"psnr_reflection_db", s.psnrDb},
                                               {"coverage", s.coverage},
                                               {"gpu_ms", ms},
                                               {"error_share_worst_1pct", breakdown.worst1PercentShare},
                                               {"error_share_worst_10pct", breakdown.worst10PercentShare}};
            summary["cameras"][cam.name][t].update(glass);
            if (scoresAll) {
                const ReflectionScore a = scoreReflection(reflection, allPixels, exposure);
                const nlohmann::json all = {{"psnr_db_all", compositedPsnrDb(r.image, ref.image, allPixels)},
                                            {"psnr_reflection_db_all", a.psnrDb},
                                            {"coverage_all", a.coverage},
                                            {"scored_pixels_all", a.maskPixels}};
                metrics["techniques"][t].update(all);
                summary["cameras"][cam.name][t].update(all);
                std::printf("ppr: %-8s %-7s all reflector pixels: PSNR %6.2f dB (reflection alone %6.2f dB)  coverage %.4f\n",
                            cam.name.c_str(), t.c_str(), all["psnr_db_all"].get<double>(), a.psnrDb, a.coverage);
            }
            if (glass.contains("glass_unscored"))
                std::printf("ppr: %-8s %-7s glass: not scored: %s\n", cam.name.c_str(), t.c_str(), glass["glass_unscored"].get<std::string>().c_str());
            else if (!glass.empty())
                std::printf("ppr: %-8s %-7s glass: PSNR %6.2f dB (reflection alone %6.2f dB)  coverage %.4f  over %llu texels\n",
                            cam.name.c_str(), t.c_str(), glass["psnr_db_glass"].get<double>(), glass["psnr_reflection_db_glass"].get<double>(),
                            glass["coverage_glass"].get<double>(), static_cast<unsigned long long>(glass["scored_texels_glass"].get<uint64_t>()));
            finals.push_back({t + " (final)", r.image});
            finals.back().label = t + ": " + fixedText(psnr, 1) + " dB as composited";
            reflections.push_back({t + " reflection: " + fixedText(s.psnrDb, 1) + " dB, coverage " + fixedText(s.coverage, 3),
                                   reflectionDisplayImage(reflection, exposure)});
            errors.push_back({t + " error (white = 0.25)", heat});
            std::printf("ppr: %-8s %-7s PSNR %6.2f dB (reflection alone %6.2f dB)  coverage %.4f  %8.2f ms GPU (technique passes)\n",
                        cam.name.c_str(), t.c_str(), psnr, s.psnrDb, s.coverage, ms);
            std::printf("ppr: %-8s %-7s error: worst 1%% of pixels %4.1f%%, worst 10%% %4.1f%%;", cam.name.c_str(), t.c_str(),
                        100.0 * breakdown.worst1PercentShare, 100.0 * breakdown.worst10PercentShare);
            for (size_t c = 0; c < kErrorClassCount; ++c)
                if (breakdown.pixels[c]) std::printf(" %s %.1f%%", errorClassName(static_cast<ErrorClass>(c)), 100.0 * breakdown.share[c]);
            std::printf("\n");
        }
        finals.push_back({truth + " reference (final)", ref.image});
        reflections.push_back({truth + " reference reflection", reflectionDisplayImage(ref.reflection, exposure)});
        const util::Rgba8Image scored = scoredPixelsImage(ref.reflection, ref.image);
        util::writePng((dir / "scored_pixels.png").string(), scored);
        util::writePng((dir / "error_classes.png").string(), errorClassImage(ref.reflection, ref.reflectedPath, ref.image));
        errors.push_back({"scored pixels (white)", scored});
        std::vector<ContactTile> tiles = finals;
        tiles.insert(tiles.end(), reflections.begin(), reflections.end());
        tiles.insert(tiles.end(), errors.begin(), errors.end());
        util::writePng((dir / "contact.png").string(), makeContactSheet(tiles, static_cast<uint32_t>(finals.size())));
        metrics["images"] = {{"contact", "contact.png"}};
        metrics["validation"] = ctx.validationEnabled();
        metrics["validation_errors"] = ctx.validationErrors() - errorsBefore;
        writeJsonFile((dir / "metrics.json").string(), metrics);
        std::printf("ppr: %-8s -> %s\n", cam.name.c_str(), (dir / "contact.png").c_str());
    }
    if (!session.singleCamera()) {
        summary["validation_errors"] = ctx.validationErrors();
        writeJsonFile((std::filesystem::path(o.out) / "metrics.json").string(), summary);
    }
    return session.finish();
}

}  // namespace ppr::app
