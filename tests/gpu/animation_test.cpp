// The default scene's moving object (ball_red bobs: glTF node animation, docs/temporal.md): at rest
// without a scene time, moved by the animation's clock in every technique, the ray-traced reference's
// TLAS rebuilt so that it still agrees with the planar one, per-object motion vectors where it moves
// and nowhere else, and the `animate` path; validation + synchronization validation on.
#include "common/reflection.h"
#include "metrics/compare_metrics.hpp"
#include "gpu_test_util.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace ppr::test {
namespace {

constexpr VkExtent2D kSize{320, 180};
constexpr double kRaised = 1.0;  // seconds: the ball at the top of its bob, 0.5 m above its rest

app::CaptureResult at(GpuFixture& f, const std::string& technique, std::optional<double> seconds, const std::string& camera = "puddles") {
    f.headless->setTechnique(technique);
    f.headless->setSceneTime(seconds);
    return f.headless->capture(f.camera(camera), kSize, 1, false, true);
}

size_t differingPixels(const util::Rgba8Image& a, const util::Rgba8Image& b) {
    size_t n = 0;
    for (size_t i = 0; i + 3 < a.pixels.size(); i += 4)
        if (a.pixels[i] != b.pixels[i] || a.pixels[i + 1] != b.pixels[i + 1] || a.pixels[i + 2] != b.pixels[i + 2]) ++n;
    return n;
}

// Reflector pixels whose reflection (class kReflectionHit in both) differs by more than `tolerance`.
size_t differingReflections(const app::FloatImage& a, const app::FloatImage& b, float tolerance) {
    size_t n = 0;
    for (size_t i = 0; i < size_t(a.width) * a.height; ++i) {
        if (a.rgba[i * 4 + 3] != gpu::kReflectionHit || b.rgba[i * 4 + 3] != gpu::kReflectionHit) continue;
        for (int c = 0; c < 3; ++c)
            if (std::abs(a.rgba[i * 4 + c] - b.rgba[i * 4 + c]) > tolerance) {
                ++n;
                break;
            }
    }
    return n;
}

TEST(Animation, TheDefaultSceneHasOneMovingObjectAtRestUnlessTimed) {
    GpuFixture f;
    ASSERT_EQ(f.scene.animation.draws.size(), 1u);
    EXPECT_EQ(f.scene.draws[f.scene.animation.draws[0]].nodeName, "ball_red");
    const app::CaptureResult rest = at(f, "ppr", std::nullopt);
    const app::CaptureResult start = at(f, "ppr", 0.0);
    const app::CaptureResult raised = at(f, "ppr", kRaised);
    const app::CaptureResult restAgain = at(f, "ppr", std::nullopt);
    EXPECT_TRUE(identical(rest.image, start.image)) << "the animation starts at the rest pose";
    EXPECT_TRUE(identical(rest.image, restAgain.image)) << "no scene time renders the loaded pose, whatever came before";
    const size_t moved = differingPixels(rest.image, raised.image);
    std::printf("puddles %ux%u: %zu pixels change when the ball rises\n", kSize.width, kSize.height, moved);
    EXPECT_GT(moved, 200u);
    EXPECT_LT(moved, size_t(kSize.width) * kSize.height / 4) << "only the ball, its shadow and its reflections move";
    EXPECT_EQ(f.ctx->validationErrors(), 0u);
}

// The planar reference re-renders the scene mirrored, so it shows the ball wherever it is. The ray-
// traced one agrees with it only if its TLAS was rebuilt with the ball's new transform.
TEST(Animation, RaytracedReferenceFollowsTheMovingObject) {
    PPR_SKIP_WITHOUT_RAY_QUERY();
    GpuFixture f;
    f.headless->settings().apply("normalmap=off");
    const float exposure = static_cast<float>(f.headless->settings().number("exposure"));
    const app::CaptureResult planarRest = at(f, "planar", std::nullopt);
    const app::CaptureResult planarRaised = at(f, "planar", kRaised);
    const app::CaptureResult rtRaised = at(f, "raytraced", kRaised);
    const app::CaptureResult rtRest = at(f, "raytraced", std::nullopt);
    const size_t ballReflection = differingReflections(planarRest.reflection, planarRaised.reflection, 0.05f);
    const size_t rtOff = differingReflections(rtRaised.reflection, planarRaised.reflection, 0.05f);
    const size_t rtRestOff = differingReflections(rtRest.reflection, planarRest.reflection, 0.05f);
    const app::ReflectionScore s = app::scoreReflection(rtRaised.reflection, planarRaised.reflection, exposure);
    std::printf("ball raised: %zu reflection pixels change in planar; raytraced differs from planar in %zu (at rest %zu), %.2f dB\n",
                ballReflection, rtOff, rtRestOff, s.psnrDb);
    ASSERT_GT(ballReflection, 30u) << "the ball's reflection must move for this test to mean anything";
    EXPECT_LE(rtOff, ballReflection / 10) << "a stale TLAS would leave the ball's reflection where it was";
    EXPECT_LE(rtRestOff, ballReflection / 10) << "and back at rest, the TLAS follows it down again";
    EXPECT_EQ(f.ctx->validationErrors(), 0u);
}

// With a still camera, TAA's motion is the objects' own: the motion debug view lights up on the
// moving ball (seen directly) and stays black everywhere else.
TEST(Animation, PerObjectMotionVectorsOnlyWhereSomethingMoves) {
    GpuFixture f;
    f.headless->setTechnique("ppr");
    f.headless->settings().set("debug", "motion");
    const scene::CameraPose cam = f.camera("puddles");
    f.headless->setSceneTime(0.4);
    const util::Rgba8Image first = f.headless->capture(cam, kSize, 1, false, false, true).image;
    f.headless->setSceneTime(0.5);
    const util::Rgba8Image moving = f.headless->capture(cam, kSize, 1, false, false, false).image;
    // Far pixels show a hint of reprojection round-off even on a still camera (as before anything
    // moved); what counts is what the ball's motion adds to the shot's first, motionless frame.
    size_t lit = 0;
    for (size_t i = 0; i + 3 < moving.pixels.size(); i += 4) {
        int change = 0;
        for (int c = 0; c < 3; ++c) change += std::abs(int(moving.pixels[i + c]) - int(first.pixels[i + c]));
        if (change > 12) ++lit;
    }
    std::printf("motion view: %zu pixels move between t=0.4 s and 0.5 s\n", lit);
    EXPECT_GT(lit, 50u) << "the ball moves up the screen";
    EXPECT_LT(lit, size_t(kSize.width) * kSize.height / 20) << "and nothing else does";
    EXPECT_EQ(f.ctx->validationErrors(), 0u);
}

// TAA's reflection history under a still camera while the ball moves. Its reflected points carry the
// ball's motion slot (the path image's tag), so `virtual` fetches the history where the ball's
// reflection was last frame. `surface` fetches it at the still surface and drags the old reflection
// along, a trail that the clipping box cannot remove within a fast move (and so did `virtual` before
// it knew the slot: with nothing moving but the object, the two fetch the same texel).
// Scored on the final frame against the same frame without AA, over the pixels the ball's reflection
// swept (reflector pixels whose reflection changed between the first and the last frame).
double sweptPsnrDb(GpuFixture& f, const std::string& technique, const std::string& reproject) {
    const scene::CameraPose cam = f.camera("puddles");
    f.headless->setTechnique(technique);
    f.headless->settings().apply("taa=1");
    f.headless->settings().apply("reproject=" + reproject);
    constexpr int kFrames = 10;
    constexpr double kStart = 0.3, kStep = 1.0 / 20.0;  // fast: the ball rises about 5 pixels a frame
    util::Rgba8Image taa;
    for (int k = 0; k < kFrames; ++k) {
        f.headless->setSceneTime(kStart + kStep * k);
        taa = f.headless->capture(cam, kSize, 1, false, false, k == 0).image;
    }
    f.headless->settings().apply("taa=0");
    const app::CaptureResult last = f.headless->capture(cam, kSize, 1, false, true);
    f.headless->setSceneTime(kStart);
    const app::CaptureResult first = f.headless->capture(cam, kSize, 1, false, true);
    double squared = 0.0;
    size_t swept = 0;
    for (size_t i = 0; i + 3 < taa.pixels.size(); i += 4) {
        if (last.reflection.rgba[i + 3] == gpu::kReflectionNone) continue;
        float change = 0.0f;
        for (int c = 0; c < 3; ++c) change = std::max(change, std::abs(last.reflection.rgba[i + c] - first.reflection.rgba[i + c]));
        if (change < 0.05f) continue;
        ++swept;
        for (int c = 0; c < 3; ++c) squared += std::pow(double(taa.pixels[i + c]) - double(last.image.pixels[i + c]), 2.0);
    }
    EXPECT_GT(swept, 100u) << technique << ": the ball's reflection must move for this to mean anything";
    return 10.0 * std::log10(255.0 * 255.0 / std::max(squared / (3.0 * double(swept)), 1e-6));
}

TEST(Animation, ReflectionHistoryFollowsTheMovingObject) {
    GpuFixture f;
    f.headless->settings().apply("normalmap=off");
    // The least gain over `surface` (dB). The exact references reflect every point of the ball; the
    // screen-space techniques only the part the camera sees, so they gain less. Measured on lavapipe
    // with the slot, taa_split=1 and taa_average=1: planar +3.9, raytraced +3.9, ssr-hiz +1.7, ppr 0.0
    // (with taa_still_range=1 and taa_still_keep=1, 2026-12-06: +3.9, +3.9, +1.4, 0.00; a keep that
    // ignored the moving draw's reflection beside took ppr to -0.2: docs/temporal.md; with
    // taa_moving_edge=1, 2026-12-07: +2.75, +2.75, +1.07, +0.02: the neighbourhood's mean, which stands in
    // for a rejected edge pixel's history, is farther from this frame without AA than one sharp sample)
    // (taa_average=0: planar +4.1, raytraced +4.1, ssr-hiz +1.1, ppr +0.04; with
    // taa_split=0 +2.4, +2.4, +0.9, +0.3: there the frame's TAA smeared `surface`'s reflection a second
    // time, and PPR, which reflects only the ball's visible side, gains least); without the slot +0.4,
    // +0.4, +0.4, 0.0. PPR's bound says only that `virtual` loses nothing.
    std::vector<std::pair<std::string, double>> techniques{{"planar", 1.5}, {"ppr", -0.1}, {"ssr-hiz", 0.7}};
    if (rayQueryMissing().empty()) techniques.emplace_back("raytraced", 1.5);
    for (const auto& [technique, gain] : techniques) {
        const double surface = sweptPsnrDb(f, technique, "surface");
        const double objectAware = sweptPsnrDb(f, technique, "virtual");
        std::printf("%s, where the ball's reflection swept: reproject=surface %.2f dB, virtual %.2f dB\n", technique.c_str(), surface,
                    objectAware);
        EXPECT_GT(objectAware, surface + gain) << technique;
    }
    EXPECT_EQ(f.ctx->validationErrors(), 0u);
}

// taa_moving_edge=1: the bobbing ball's reflection in the far wall mirror is a few pixels wide, and the
// jitter flips its edge pixels between the ball and what lies behind it. Beside a moving draw's
// reflection the path's depth rejects such a pixel's history every other frame; restarting from the
// neighbourhood's mean instead of one jittered sample brings it closer to the supersampled reference
// and changes it less. Measured on lavapipe (planar, mirror, 160x90, 24 frames): reflector pixels
// 32.67 against 32.22 dB, flicker 0.179 against 0.192 levels.
TEST(Animation, MovingEdgeMeanCalmsAMovingReflectionsEdge) {
    auto dir = tempDir("moving-edge");
    RunResult r = runPpr("compare --validation --path animate --frames 24 --camera mirror --size 160x90 --technique planar@taa=1 "
                         "--technique planar@taa=1,taa_moving_edge=0 --out " + dir.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    std::ifstream in(dir / "metrics.json");
    const nlohmann::json m = nlohmann::json::parse(in);
    const nlohmann::json& on = m["techniques"]["planar@taa=1"]["temporal"];
    const nlohmann::json& off = m["techniques"]["planar@taa=1,taa_moving_edge=0"]["temporal"];
    std::printf("mirror, ball bobbing: reflector pixels %.2f against %.2f dB, flicker %.3f against %.3f levels\n",
                on["reflector_psnr_db_mean"].get<double>(), off["reflector_psnr_db_mean"].get<double>(), on["flicker"].get<double>(),
                off["flicker"].get<double>());
    EXPECT_GT(on["reflector_psnr_db_mean"].get<double>(), off["reflector_psnr_db_mean"].get<double>() + 0.2);
    EXPECT_LT(on["flicker"].get<double>(), off["flicker"].get<double>());
    std::filesystem::remove_all(dir);
}

// taa_moving_filter: the bobbing ball's edge pixels blend the current frame reconstructed at their
// centre, not the one sample the jitter put on either side of the edge, and change less from frame to
// frame. Measured on lavapipe (planar, puddles, 160x90, 24 frames): flicker 0.208 against 0.219
// levels, the whole frame 37.23 against 37.24 dB. Where nothing moves (a strafe) no pixel takes the
// filter: the frames' scores are the same to the last bit.
TEST(Animation, MovingFilterCalmsAMovingObjectsEdgeAndLeavesAStillSceneAlone) {
    auto dir = tempDir("moving-filter");
    RunResult r = runPpr("compare --validation --path animate --frames 24 --camera puddles --size 160x90 --technique planar@taa=1 "
                         "--technique planar@taa=1,taa_moving_filter=0 --out " + dir.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    nlohmann::json m = nlohmann::json::parse(std::ifstream(dir / "metrics.json"));
    const nlohmann::json on = m["techniques"]["planar@taa=1"]["temporal"];
    const nlohmann::json off = m["techniques"]["planar@taa=1,taa_moving_filter=0"]["temporal"];
    std::printf("puddles, ball bobbing: flicker %.4f against %.4f levels, whole frame %.3f against %.3f dB\n", on["flicker"].get<double>(),
                off["flicker"].get<double>(), on["psnr_db_mean"].get<double>(), off["psnr_db_mean"].get<double>());
    EXPECT_LT(on["flicker"].get<double>(), off["flicker"].get<double>() - 0.005);
    EXPECT_GT(on["psnr_db_mean"].get<double>(), off["psnr_db_mean"].get<double>() - 0.1);

    r = runPpr("compare --validation --path strafe --frames 8 --camera puddles --size 96x54 --technique ppr@taa=1 "
               "--technique ppr@taa=1,taa_moving_filter=0 --out " + dir.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    m = nlohmann::json::parse(std::ifstream(dir / "metrics.json"));
    const nlohmann::json still = m["techniques"]["ppr@taa=1"]["temporal"];
    const nlohmann::json stillOff = m["techniques"]["ppr@taa=1,taa_moving_filter=0"]["temporal"];
    for (const char* key : {"psnr_db_mean", "reflector_psnr_db_mean", "scored_psnr_db_mean"})
        EXPECT_EQ(still[key].get<double>(), stillOff[key].get<double>()) << key;
    std::filesystem::remove_all(dir);
}

// The camera stands still while the scene moves: flicker is the change the reference does not make
// (meanAbsoluteExcessChange), so the ball's own motion is not counted.
TEST(Animation, AnimatePathRunsTheClockOnAStillCamera) {
    auto dir = tempDir("path-animate");
    const std::string raytraced = rayQueryMissing().empty() ? " --technique raytraced" : "";  // where the device has ray queries
    RunResult r = runPpr("compare --validation --path animate --frames 4 --camera puddles --size 96x54 --technique ppr --technique "
                         "ppr@taa=1" + raytraced + " --out " + dir.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    std::ifstream in(dir / "metrics.json");
    const nlohmann::json m = nlohmann::json::parse(in);
    EXPECT_EQ(m["still"], true) << "a still camera on a moving scene";
    ASSERT_TRUE(m["techniques"]["ppr"]["temporal"]["flicker"].is_number());
    // Per frame, temporal.csv gives the raw change and the change beyond the reference's.
    std::ifstream csv(dir / "temporal.csv");
    std::string line;
    std::getline(csv, line);
    EXPECT_NE(line.find("change,excess_change"), std::string::npos) << line;
    size_t rows = 0;
    while (std::getline(csv, line)) {
        if (line.rfind("\"ppr\",", 0) != 0) continue;
        std::vector<double> v;
        std::stringstream fields(line.substr(6));
        for (std::string x; std::getline(fields, x, ',');) v.push_back(std::stod(x));
        // after the name: frame, x, y, z, yaw, pitch, psnr, reflector psnr, change, excess, ms, scored psnr
        ASSERT_EQ(v.size(), 12u) << line;
        EXPECT_GE(v[9], 0.0) << line;
        ++rows;
    }
    EXPECT_EQ(rows, 4u);
    EXPECT_EQ(m["techniques"]["ppr@taa=1"]["temporal"]["frames"], 4);
    std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace ppr::test
