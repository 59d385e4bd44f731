// `--path` through the ppr executable: compare scores every frame of a path against the supersampled
// reference (metrics.json's "temporal" block, temporal.csv, temporal.png), capture writes every frame,
// and a bad path file is one line naming the file and line.
#include "gpu_test_util.hpp"

#include <nlohmann/json.hpp>

#include <fstream>
#include <utility>

namespace ppr::test {
namespace {

// `ppr compare --validation ARGS --out DIR` on a path: its metrics.json (the test fails on a non-zero
// exit or any validation error).
nlohmann::json validatedCompare(const std::filesystem::path& dir, const std::string& args) {
    const RunResult r = runPpr("compare --validation " + args + " --out " + dir.string());
    EXPECT_EQ(r.exitCode, 0) << r.output;
    if (r.exitCode != 0) return nlohmann::json::object();
    nlohmann::json m = readJson(dir / "metrics.json");
    EXPECT_EQ(m["validation_errors"], 0);
    return m;
}

// A row's mean reflector-pixel PSNR along the path.
double reflectorDb(const nlohmann::json& m, const std::string& row) {
    return m.at("techniques").at(row).at("temporal").at("reflector_psnr_db_mean").get<double>();
}

// Both rows' means along the wall mirror's 16-frame strafe at 320x180 (whole frame, reflector pixels),
// where a motion-only TAA setting is judged; printed for the comments' measured values.
struct StrafeScores {
    double frame, reflector;
};
std::pair<StrafeScores, StrafeScores> mirrorStrafe(const std::filesystem::path& dir, const std::string& row, const std::string& baseline) {
    const nlohmann::json m =
        validatedCompare(dir, "--path strafe --frames 16 --camera mirror --size 320x180 --technique " + row + " --technique " + baseline);
    const auto scores = [&](const std::string& r) {
        return StrafeScores{m.at("techniques").at(r).at("temporal").at("psnr_db_mean").get<double>(), reflectorDb(m, r)};
    };
    const StrafeScores a = scores(row), b = scores(baseline);
    std::printf("mirror, strafe: %s %.2f dB whole frame, %.2f dB reflector pixels; %s %.2f, %.2f dB\n", row.c_str(), a.frame, a.reflector,
                baseline.c_str(), b.frame, b.reflector);
    std::filesystem::remove_all(dir);
    return {a, b};
}

// A still path (puddles, 20 frames) renders frames 1 and 19 the same with both rows: what a setting that
// acts only on motion must leave alone.
void expectSameStillFrames(const std::filesystem::path& dir, const std::string& baseline, const std::string& row) {
    const nlohmann::json still =
        validatedCompare(dir, "--path still --frames 20 --camera puddles --size 160x90 --technique " + baseline + " --technique " + row);
    const std::string baselineFrames = still["techniques"][baseline]["frames_dir"];
    const std::string rowFrames = still["techniques"][row]["frames_dir"];
    for (const char* frame : {"frame_001.png", "frame_019.png"})
        EXPECT_EQ(util::readPng((dir / rowFrames / frame).string()).pixels, util::readPng((dir / baselineFrames / frame).string()).pixels)
            << row << ' ' << frame;
    std::filesystem::remove_all(dir);
}

size_t lineCount(const std::filesystem::path& p) {
    std::ifstream f(p);
    size_t n = 0;
    for (std::string line; std::getline(f, line);) ++n;
    return n;
}

TEST(CameraPathRun, CompareScoresEveryFrameOfAStrafe) {
    auto dir = tempDir("path-compare");
    RunResult r = runPpr("compare --validation --path strafe --frames 4 --camera puddles --size 160x90 --technique ppr --technique ppr@taa=1 --out " +
                         dir.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const nlohmann::json m = readJson(dir / "metrics.json");
    EXPECT_EQ(m["validation_errors"], 0);
    EXPECT_EQ(m["path"], "strafe");
    EXPECT_EQ(m["frames"], 4);
    EXPECT_EQ(m["still"], false);
    for (const char* t : {"ppr", "ppr@taa=1"}) {
        const nlohmann::json& temporal = m["techniques"][t]["temporal"];
        for (const char* key : {"psnr_db_mean", "reflector_psnr_db_mean", "scored_psnr_db_mean", "flicker", "frames"})
            EXPECT_TRUE(temporal.contains(key)) << t << key;
        EXPECT_EQ(temporal["frames"], 4);
        EXPECT_TRUE(temporal["flicker"].is_null()) << "flicker is measured on a still camera only";
        EXPECT_GT(temporal["psnr_db_mean"].get<double>(), 15.0) << t;
        // PPR leaves the puddles' off-screen reflections (sky, the walls behind the camera) black
        // (fallback_env=0): the reflector pixels score them, the scored pixels leave them out.
        EXPECT_GT(temporal["scored_psnr_db_mean"].get<double>(), temporal["reflector_psnr_db_mean"].get<double>() + 3.0) << t;
        EXPECT_TRUE(std::filesystem::exists(dir / m["techniques"][t]["frames_dir"].get<std::string>() / "frame_003.png")) << t;
    }
    EXPECT_EQ(lineCount(dir / "temporal.csv"), 1u + 2u * 4u);
    EXPECT_TRUE(std::filesystem::exists(dir / "temporal.png"));
    EXPECT_EQ(m["images"]["strip"], "strip.png");
    EXPECT_TRUE(std::filesystem::exists(dir / "strip.png"));
    std::filesystem::remove_all(dir);
}

// The reflection's own history: reprojected through the virtual point it stays closer to the
// supersampled reference under a strafe than fetched by the surface's motion or the seed note's
// candidates. Every row is one shot from the same jitter sample, so frame 0 is the same picture.
// Measured on lavapipe at this size (16 frames, taa_average=1, taa_motion_cap=1, taa_still_spread=1):
// surface 32.70, candidates 32.19, virtual 32.89 dB (no AA 30.7; 32.58, 32.08, 32.83 before taa_rim_keep). The whole-colour frame TAA
// (taa_split=0) is not ranked here: without the motion cap the split led it by 0.46 dB (32.85 against
// 32.39), with the cap it scores 32.87 (docs/temporal.md, Measured). At 160x90 the order of candidates
// and virtual flips: too few pixels per ripple.
TEST(CameraPathRun, VirtualReprojectionBeatsSurfaceAndCandidatesOnReflectorsUnderStrafe) {
    auto dir = tempDir("path-reproject");
    const nlohmann::json m = validatedCompare(dir, "--path strafe --frames 16 --camera puddles --size 320x180 --technique planar@taa=1,reproject=surface "
                                                   "--technique planar@taa=1,reproject=candidates --technique planar@taa=1,reproject=virtual");
    auto mode = [&](const char* name) { return reflectorDb(m, std::string("planar@taa=1,reproject=") + name); };
    std::printf("reflector pixels, strafe: surface %.2f dB, candidates %.2f dB, virtual %.2f dB\n", mode("surface"), mode("candidates"), mode("virtual"));
    EXPECT_GT(mode("virtual"), mode("surface"));
    EXPECT_GT(mode("virtual"), mode("candidates"));
    const std::string surfaceFrames = m["techniques"]["planar@taa=1,reproject=surface"]["frames_dir"];
    const std::string virtualFrames = m["techniques"]["planar@taa=1,reproject=virtual"]["frames_dir"];
    EXPECT_EQ(util::readPng((dir / surfaceFrames / "frame_000.png").string()).pixels, util::readPng((dir / virtualFrames / "frame_000.png").string()).pixels);
    std::filesystem::remove_all(dir);
}

// PPR's own reflection history, judged on what PPR can reflect (scored_psnr_db_mean: the reflected point
// on screen and unoccluded; the rest PPR leaves black and every row scores alike): through the virtual
// point it stays closer to the truth under a strafe than fetched by the surface's motion. Measured on
// lavapipe at this size (wall mirror, 16 frames): virtual 28.49 dB, surface 27.93 (at 640x360 over 32
// frames 29.09 against 27.75; over the overview's strafe there it is 0.20 dB behind, docs/temporal.md).
TEST(CameraPathRun, VirtualReprojectionKeepsPprCloserOnWhatItReflectsUnderStrafe) {
    auto dir = tempDir("path-reproject-ppr");
    const nlohmann::json m = validatedCompare(dir, "--path strafe --frames 16 --camera mirror --size 320x180 --technique ppr@taa=1,reproject=surface "
                                                   "--technique ppr@taa=1,reproject=virtual");
    auto scored = [&](const char* name) {
        return m.at("techniques").at(std::string("ppr@taa=1,reproject=") + name).at("temporal").at("scored_psnr_db_mean").get<double>();
    };
    std::printf("PPR, scored pixels, mirror strafe: surface %.2f dB, virtual %.2f dB\n", scored("surface"), scored("virtual"));
    EXPECT_GT(scored("virtual"), scored("surface") + 0.2);
    std::filesystem::remove_all(dir);
}

// A history fetched between texels is softened by each frame's Catmull-Rom fetch, and at a feedback near
// 0.97 the softening of a dozen frames adds up: under a strafe the frame's TAA scored no better than no
// AA. taa_motion_cap=1 keeps at most 0.7 of such a history (1 within a tenth of a texel of a centre),
// which a still view (history at texel centres) never reaches, so a still path renders the same frames
// either way. Measured on lavapipe at this size (mirror, 16 frames, whole frame): 33.65 dB against
// 33.28 (before taa_rim_keep 33.27 against 32.86; 32 frames: 33.44 against 32.50; the first frames,
// with equal shares, gain least).
TEST(CameraPathRun, MotionCapKeepsAMovingViewSharpAndAStillViewUnchanged) {
    auto dir = tempDir("path-motion-cap");
    const auto [capped, uncapped] = mirrorStrafe(dir, "planar@taa=1", "planar@taa=1,taa_motion_cap=0");
    EXPECT_GT(capped.frame, uncapped.frame + 0.25);
    expectSameStillFrames(dir, "planar@taa=1", "planar@taa=1,taa_motion_cap=0");
}

// taa_reflection_cap=1 puts the same cap on the reflection's own history: a reflection fetched between
// texels under motion softens less, and a still view's frames are those without it. Measured on lavapipe
// at this size (mirror, strafe, 16 frames, reflector pixels): virtual 29.89 dB against 29.57 (29.62
// against 29.32 before taa_rim_keep); surface 29.37 against 27.95 before it (it also drops a misplaced
// history sooner; docs/temporal.md).
TEST(CameraPathRun, ReflectionCapSharpensAMovingReflectionAndLeavesAStillViewUnchanged) {
    auto dir = tempDir("path-reflection-cap");
    const auto [capped, uncapped] = mirrorStrafe(dir, "planar@taa=1,taa_reflection_cap=1", "planar@taa=1");
    EXPECT_GT(capped.reflector, uncapped.reflector + 0.15);
    expectSameStillFrames(dir, "planar@taa=1", "planar@taa=1,taa_reflection_cap=1");
}

// taa_rim_keep=1: a pixel that the jitter takes off a reflector's rim while the view moves keeps its
// reflection's history (blended from the texels where its surface was that held one) for the frames that
// bring the reflection back, instead of restarting it from one jittered frame or showing a neighbour's.
// On the wall mirror that is the thin band of the frame's reflection along its top edge. A still view
// keeps its own texel either way, so its frames are the same. Measured on lavapipe at this size (mirror,
// strafe, 16 frames): whole frame 33.65 dB against 33.27, reflector pixels 29.57 against 29.32 (the
// frame's pixels beside the rim, which showed a neighbour's reflection, gain the most).
TEST(CameraPathRun, RimKeepHoldsAReflectorEdgesReflectionUnderMotionAndLeavesAStillViewUnchanged) {
    auto dir = tempDir("path-rim-keep");
    const auto [kept, restarted] = mirrorStrafe(dir, "planar@taa=1", "planar@taa=1,taa_rim_keep=0");
    EXPECT_GT(kept.frame, restarted.frame + 0.2);
    EXPECT_GT(kept.reflector, restarted.reflector + 0.05);
    expectSameStillFrames(dir, "planar@taa=1", "planar@taa=1,taa_rim_keep=0");
}

// The ray-traced reference gives its path lengths too (eye → reflector → hit), so its reflection
// history finds the virtual point instead of falling back to the surface's motion. Measured on lavapipe:
// surface 32.71, virtual 32.90 dB (32.59, 32.85 before taa_rim_keep; 32.60, 32.87 without the motion cap). At 160x90 over 8 frames, where the equal shares of a history's
// first frames (taa_average=1) weigh most, surface led (29.82 against 29.51).
TEST(CameraPathRun, RaytracedReflectionsReprojectThroughTheirVirtualPoint) {
    PPR_SKIP_WITHOUT_RAY_QUERY();
    auto dir = tempDir("path-raytraced");
    const nlohmann::json m = validatedCompare(dir, "--path strafe --frames 16 --camera puddles --size 320x180 --reference raytraced "
                                                   "--technique raytraced@taa=1,reproject=surface --technique raytraced@taa=1,reproject=virtual");
    const double surface = reflectorDb(m, "raytraced@taa=1,reproject=surface"), virtualPoint = reflectorDb(m, "raytraced@taa=1,reproject=virtual");
    std::printf("raytraced, reflector pixels, strafe: surface %.2f dB, virtual %.2f dB\n", surface, virtualPoint);
    EXPECT_GT(virtualPoint, surface);
    std::filesystem::remove_all(dir);
}

// With taa_split=0 the frame's history holds the whole colour, and the frame's TAA mixes a reflector
// pixel's history fetch at its reflection's motion in by the composite's reflection weight
// (reproject=virtual): on the wall mirror, whose colour is mostly its reflection, that is most of what
// virtual gains over surface under a strafe there. Measured on lavapipe at this size: +1.88 dB with the
// mix (+1.80 before taa_rim_keep, +1.73 without the motion cap, +2.17 before the reflection history's silhouette rule), +0.99
// with the reflection's own history alone.
TEST(CameraPathRun, FrameTaaFollowsTheReflectionOnAMirror) {
    auto dir = tempDir("path-mirror");
    const nlohmann::json m = validatedCompare(dir, "--path strafe --frames 12 --camera mirror --size 160x90 "
                                                   "--technique planar@taa=1,reproject=surface,taa_split=0 --technique planar@taa=1,reproject=virtual,taa_split=0");
    const double surface = reflectorDb(m, "planar@taa=1,reproject=surface,taa_split=0");
    const double virtualPoint = reflectorDb(m, "planar@taa=1,reproject=virtual,taa_split=0");
    std::printf("mirror, reflector pixels, strafe, taa_split=0: surface %.2f dB, virtual %.2f dB\n", surface, virtualPoint);
    EXPECT_GT(virtualPoint, surface + 1.2);
    std::filesystem::remove_all(dir);
}

// SSR gives path lengths from its hits (eye → surface → the point seen at the hit pixel): its
// `virtual` rows no longer fall back to the surface's motion, so they differ from `surface`.
TEST(CameraPathRun, SsrReflectionsReprojectThroughTheirVirtualPoint) {
    auto dir = tempDir("path-ssr");
    const nlohmann::json m = validatedCompare(dir, "--path strafe --frames 6 --camera overview --size 160x90 "
                                                   "--technique ssr-hiz@taa=1,reproject=surface --technique ssr-hiz@taa=1,reproject=virtual "
                                                   "--technique ssr-linear@taa=1,reproject=virtual --technique ssr-hiz@taa=1,reproject=virtual,indirect=0");
    const double surface = reflectorDb(m, "ssr-hiz@taa=1,reproject=surface"), virtualPoint = reflectorDb(m, "ssr-hiz@taa=1,reproject=virtual");
    const double wholeScreen = reflectorDb(m, "ssr-hiz@taa=1,reproject=virtual,indirect=0");
    std::printf("ssr-hiz, reflector pixels, strafe: surface %.3f dB, virtual %.3f dB (whole-screen dispatch %.3f)\n", surface, virtualPoint, wholeScreen);
    EXPECT_NE(surface, virtualPoint);
    // The tile lists and the whole-screen dispatch write the same path lengths.
    EXPECT_EQ(virtualPoint, wholeScreen);
    std::filesystem::remove_all(dir);
}

TEST(CameraPathRun, StillPathMeasuresFlicker) {
    auto dir = tempDir("path-still");
    RunResult r = runPpr("compare --path still --frames 4 --camera overview --size 96x54 --technique planar --out " + dir.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const nlohmann::json m = readJson(dir / "metrics.json");
    EXPECT_EQ(m["still"], true);
    // Without TAA a still camera renders the same frame again: no flicker at all.
    EXPECT_EQ(m["techniques"]["planar"]["temporal"]["flicker"], 0.0);
    std::filesystem::remove_all(dir);
}

TEST(CameraPathRun, CaptureAlongAPathFileAndItsErrors) {
    auto dir = tempDir("path-capture");
    const std::filesystem::path file = dir / "walk.txt";
    std::ofstream(file) << "# two poses\n0,1.6,4,0,-10\n0.1,1.6,4,0,-10,50\n";
    RunResult r = runPpr("capture --set taa=1 --path " + file.string() + " --size 96x54 --out " + (dir / "out").string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const nlohmann::json report = readJson(dir / "out" / "report.json");
    EXPECT_EQ(report["frames"], 2);
    EXPECT_TRUE(std::filesystem::exists(dir / "out" / "frames" / "frame_001.png"));
    EXPECT_EQ(lineCount(dir / "out" / "frames.csv"), 3u);

    std::ofstream(file) << "0,1.6,4,0,-10\nhall\n";
    r = runPpr("capture --path " + file.string() + " --size 96x54 --out " + (dir / "bad").string());
    EXPECT_NE(r.exitCode, 0);
    EXPECT_NE(r.output.find("walk.txt:2: expected x,y,z"), std::string::npos) << r.output;
    r = runPpr("capture --path " + (dir / "missing.txt").string() + " --size 96x54 --out " + (dir / "bad").string());
    EXPECT_NE(r.exitCode, 0);
    EXPECT_NE(r.output.find("missing.txt: cannot read"), std::string::npos) << r.output;
    r = runPpr("bench --path strafe --out " + (dir / "bad").string());
    EXPECT_NE(r.exitCode, 0);
    EXPECT_NE(r.output.find("only capture and compare"), std::string::npos) << r.output;
    std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace ppr::test
