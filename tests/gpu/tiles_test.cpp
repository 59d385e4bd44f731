// PPR at scale: per-tile reflector culling and indirect dispatch change no pixel, the indirect
// arguments are what the view needs, culling does cull, and a reflector set above the budget
// renders with a warning. Validation + synchronization validation on throughout.
#include "gpu_test_util.hpp"
#include "techniques/technique_table.hpp"
#include "common/reflector_buffer.hpp"
#include "ppr_common/encoding.h"
#include "ppr_common/tile_culling.h"
#include "ppr_common/tiles.h"
#include "ppr_project/ppr_project_pass.hpp"
#include "ppr_project/project_threads.hpp"
#include "ppr_reach/ppr_reach_pass.hpp"
#include "tile_classify/tile_classify_pass.hpp"
#include "vk/live_objects.hpp"
#include "scene/camera.hpp"
#include "scene/reflector_groups.hpp"
#include "scene/stress_scene.hpp"

#include <nlohmann/json.hpp>

#include <cstring>
#include <fstream>
#include <span>

namespace ppr::test {
namespace {

constexpr VkExtent2D kSize{480, 270};  // not a multiple of the tile size: partial tiles at the edges

struct Frame {
    app::FloatImage reflection;
    app::CaptureResult capture;
};

Frame render(GpuFixture& f, const scene::CameraPose& camera, const std::string& tiles, const std::string& indirect,
             const std::string& debug = "none") {
    f.headless->setTechnique("ppr");
    f.headless->settings().set("tiles", tiles);
    f.headless->settings().set("indirect", indirect);
    f.headless->settings().set("debug", debug);
    Frame fr;
    fr.capture = f.headless->capture(camera, kSize, 1, false, true);
    fr.reflection = fr.capture.reflection;
    return fr;
}

bool identical(const app::FloatImage& a, const app::FloatImage& b) {
    return a.width == b.width && a.height == b.height && a.rgba.size() == b.rgba.size() &&
           std::memcmp(a.rgba.data(), b.rgba.data(), a.rgba.size() * sizeof(float)) == 0;
}

size_t reflectedPixels(const app::FloatImage& img) {
    size_t n = 0;
    for (size_t i = 3; i < img.rgba.size(); i += 4) n += img.rgba[i] > 0.0f;
    return n;
}

// Every toggle combination gives the bit-identical reflection image of tiles=0 indirect=0, and the
// whole-screen decoded intermediate buffer (debug=intermediate) is identical with culling on and off.
void expectTogglesChangeNothing(GpuFixture& f, const std::string& camera) {
    const scene::CameraPose pose = f.camera(camera);
    const Frame reference = render(f, pose, "0", "0");
    ASSERT_GT(reflectedPixels(reference.reflection), 100u) << camera << ": the view should show reflections";
    for (const auto& [tiles, indirect] : {std::pair{"1", "1"}, std::pair{"1", "0"}, std::pair{"0", "1"}})
        EXPECT_TRUE(identical(render(f, pose, tiles, indirect).reflection, reference.reflection))
            << camera << ": tiles=" << tiles << " indirect=" << indirect << " differs from tiles=0 indirect=0";
    EXPECT_TRUE(identical(render(f, pose, "1", "1", "intermediate").reflection, render(f, pose, "0", "1", "intermediate").reflection))
        << camera << ": the intermediate buffer differs with culling on and off";
}

TEST(PprTiles, CullingAndIndirectAreBitIdenticalOnTheDefaultScene) {
    GpuFixture f;
    for (const char* camera : {"overview", "puddles", "grazing", "stairs", "mirror"}) expectTogglesChangeNothing(f, camera);
    EXPECT_EQ(f.ctx->validationErrors(), 0u);
}

TEST(PprTiles, CullingAndIndirectAreBitIdenticalOnTheStressScene) {
    GpuFixture f(scene::makeStressScene(256));
    for (const char* camera : {"overview", "reflective_5", "reflective_25"}) expectTogglesChangeNothing(f, camera);
    EXPECT_EQ(f.ctx->validationErrors(), 0u);
}

// A workgroup width a pass offers by setting (project_threads, classify_threads): any gives the
// same reflection and intermediate buffer as the first offered one, with culling on and off.
struct WidthSetting {
    const char* key;
    std::span<const uint32_t> offered;
    uint32_t (*deviceDefault)(const vk::DeviceInfo&);  // the pass's autoThreads
};

// Returns the pipelines made while the widths were tried.
int64_t expectWidthsChangeNothing(GpuFixture& f, const std::string& camera, const WidthSetting& w) {
    const scene::CameraPose pose = f.camera(camera);
    const std::string first = std::to_string(w.offered.front());
    int64_t made = 0;
    for (const char* tiles : {"1", "0"}) {
        f.headless->settings().set(w.key, first);
        const Frame reference = render(f, pose, tiles, "1"), intermediate = render(f, pose, tiles, "1", "intermediate");
        EXPECT_GT(reflectedPixels(reference.reflection), 100u) << camera << ": the view should show reflections";
        const int64_t before = vk::liveObjects().pipelines;
        for (uint32_t width : w.offered) {
            f.headless->settings().set(w.key, std::to_string(width));
            EXPECT_TRUE(identical(render(f, pose, tiles, "1").reflection, reference.reflection))
                << camera << ": " << w.key << "=" << width << " tiles=" << tiles << " changes the reflection";
            EXPECT_TRUE(identical(render(f, pose, tiles, "1", "intermediate").reflection, intermediate.reflection))
                << camera << ": " << w.key << "=" << width << " tiles=" << tiles << " changes the intermediate buffer";
        }
        made += vk::liveObjects().pipelines - before;
    }
    f.headless->settings().set(w.key, "auto");
    return made;
}

void expectWidthsChangeNothing(const WidthSetting& w) {
    {
        GpuFixture f;
        // One pipeline per width not made before (the device's default, made up front, and the
        // reference's), once: none on a second view.
        const int64_t fresh = int64_t(w.offered.size()) - (w.deviceDefault(f.ctx->info()) == w.offered.front() ? 1 : 2);
        EXPECT_EQ(expectWidthsChangeNothing(f, "overview", w), fresh) << w.key;
        EXPECT_EQ(expectWidthsChangeNothing(f, "mirror", w), 0) << w.key;
        EXPECT_EQ(f.ctx->validationErrors(), 0u);
    }
    GpuFixture f(scene::makeStressScene(1024));
    expectWidthsChangeNothing(f, "reflective_25", w);
    EXPECT_EQ(f.ctx->validationErrors(), 0u);
}

TEST(PprTiles, EveryProjectionWidthGivesTheSameImages) {
    expectWidthsChangeNothing({"project_threads", passes::kProjectThreadChoices, &passes::PprProjectPass::autoThreads});
}

TEST(PprTiles, EveryClassificationWidthGivesTheSameImages) {
    expectWidthsChangeNothing({"classify_threads", passes::kClassifyThreadChoices, &passes::TileClassifyPass::autoThreads});
}

TEST(PprTiles, EveryReachWidthGivesTheSameImages) {
    expectWidthsChangeNothing({"reach_threads", passes::kReachThreadChoices, &passes::PprReachPass::autoThreads});
}

TEST(PprTiles, CullingKeepsFewReflectorsPerTile) {
    GpuFixture f(scene::makeStressScene(256));
    const Frame on = render(f, f.camera("overview"), "1", "1");
    ASSERT_TRUE(on.capture.pprStats);
    const gpu::PprFrameStats& s = *on.capture.pprStats;
    const uint64_t unculled = uint64_t(s.tilesWithContent) * 256;
    std::printf("pairs kept %u of %llu, at most %u in one tile\n", s.reflectorTilePairs, static_cast<unsigned long long>(unculled),
                s.maxTileSurvivors);
    EXPECT_GT(s.reflectorTilePairs, 0u);
    EXPECT_LT(s.reflectorTilePairs, unculled / 8) << "per-tile culling should drop most (tile, reflector) pairs";
    EXPECT_LT(s.maxTileSurvivors, 256u);
    // Without culling every content tile keeps every reflector.
    const Frame off = render(f, f.camera("overview"), "0", "1");
    ASSERT_TRUE(off.capture.pprStats);
    EXPECT_EQ(off.capture.pprStats->reflectorTilePairs, unculled);
    EXPECT_EQ(f.ctx->validationErrors(), 0u);
}

// Where a tile's survivors share one plane (a floor of mirror tiles), its pixels look their reflector
// up in a grid over the plane (ppr_common/plane_grid.h) instead of testing every survivor. The grid
// runs (report.json's tiles_plane_grid) and picks what the full scan picks: the pictures with
// culling off, which scan every reflector, are the same.
TEST(PprTiles, PlaneGridPicksWhatTheFullScanPicks) {
    GpuFixture f(scene::makeStressScene(1024));
    for (const char* camera : {"overview", "reflective_25"}) {
        const Frame fr = render(f, f.camera(camera), "1", "1");
        ASSERT_TRUE(fr.capture.pprStats);
        const gpu::PprFrameStats& s = *fr.capture.pprStats;
        std::printf("%s: %u of %u tiles with survivors used the plane grid\n", camera, s.tilesOnPlaneGrid, s.tilesWithSurvivors);
        EXPECT_GT(s.tilesOnPlaneGrid, s.tilesWithSurvivors / 4) << camera;
        EXPECT_LE(s.tilesOnPlaneGrid, s.tilesWithSurvivors) << camera;
        const Frame scan = render(f, f.camera(camera), "0", "0");
        EXPECT_EQ(scan.capture.pprStats->tilesOnPlaneGrid, 0u) << camera << ": without culling there are no per-tile lists";
        EXPECT_TRUE(identical(fr.reflection, scan.reflection)) << camera << ": the grid chose differently from the full scan";
    }
    EXPECT_EQ(f.ctx->validationErrors(), 0u);
}

// The bounds pass compacts the frame's reflectors: every tile's culling and the reach pass loop over
// those on screen (either side: occluders) and those among them showing their reflecting side
// (candidates). The counts are the host's, from the same shared header (within 2: a rectangle at
// the screen's border may round the other way on the device), and the pictures are unchanged.
TEST(PprTiles, CullingLoopsOverTheReflectorsOnScreen) {
    GpuFixture f(scene::makeStressScene(1024));
    const std::vector<gpu::ReflectorData> data = passes::ReflectorBuffer::pack(f.scene.reflectors, scene::groupReflectors(f.scene.reflectors));
    const glm::vec2 screen(float(kSize.width), float(kSize.height));
    for (const char* camera : {"overview", "reflective_5", "reflective_100"}) {
        const scene::CameraPose pose = f.camera(camera);
        const glm::mat4 viewProj = scene::projectionMatrix(pose.fovYDeg, screen.x / screen.y, scene::kNearPlane) * scene::viewMatrix(pose);
        int onScreen = 0, reflecting = 0;
        for (const gpu::ReflectorData& r : data) {
            const gpu::PprReflectorBounds b = gpu::pprReflectorBounds(r, viewProj, pose.position, screen);
            if (!gpu::pprRectsOverlap(b.rect, b.rect)) continue;
            ++onScreen;
            reflecting += b.reflects != 0u;
        }
        const Frame fr = render(f, pose, "1", "1");
        ASSERT_TRUE(fr.capture.pprStats);
        const gpu::PprFrameStats& s = *fr.capture.pprStats;
        std::printf("%s: %u of 1024 on screen, %u reflecting (host: %d, %d), at most %u survive in a tile\n", camera, s.reflectorsOnScreen,
                    s.reflectorsReflecting, onScreen, reflecting, s.maxTileSurvivors);
        EXPECT_NEAR(int(s.reflectorsOnScreen), onScreen, 2) << camera;
        EXPECT_NEAR(int(s.reflectorsReflecting), reflecting, 2) << camera;
        EXPECT_LE(s.reflectorsReflecting, s.reflectorsOnScreen) << camera;
        EXPECT_LE(s.maxTileSurvivors, s.reflectorsReflecting) << camera;
        if (std::string(camera) != "overview") EXPECT_LT(s.reflectorsOnScreen, 1024u) << camera << ": the view leaves reflectors off screen";
    }
    expectTogglesChangeNothing(f, "reflective_5");
    EXPECT_EQ(f.ctx->validationErrors(), 0u);
}

// With culling and indirect dispatch the projection runs only on the tiles the reach pass lists:
// with few reflectors exactly those left with a survivor, with many (each plane's reflectors merged
// into one summary, PprCullPlaneBounds) a superset of them. The counts and the per-tile survivors (debug=tiles) are those of the
// whole-screen dispatch.
void expectReachListsTheTilesWithSurvivors(GpuFixture& f, const std::string& camera, bool exact) {
    const scene::CameraPose pose = f.camera(camera);
    const Frame listed = render(f, pose, "1", "1"), everyTile = render(f, pose, "1", "0");
    ASSERT_TRUE(listed.capture.pprStats && everyTile.capture.pprStats);
    const gpu::PprFrameStats &l = *listed.capture.pprStats, &e = *everyTile.capture.pprStats;
    const uint32_t tiles = gpu::pprTilesCovering(kSize.width) * gpu::pprTilesCovering(kSize.height);
    std::printf("%s: %u tiles, %u with content, %u with survivors, %u projected\n", camera.c_str(), tiles, l.tilesWithContent,
                l.tilesWithSurvivors, l.tilesProjected);
    EXPECT_EQ(e.tilesProjected, tiles) << camera;
    EXPECT_EQ(l.tilesWithContent, e.tilesWithContent) << camera;
    EXPECT_EQ(l.tilesWithSurvivors, e.tilesWithSurvivors) << camera;
    EXPECT_EQ(l.reflectorTilePairs, e.reflectorTilePairs) << camera;
    EXPECT_EQ(l.occluderTilePairs, e.occluderTilePairs) << camera;
    EXPECT_GT(l.tilesWithSurvivors, 0u) << camera;
    if (exact) EXPECT_EQ(l.tilesProjected, l.tilesWithSurvivors) << camera;
    else EXPECT_GE(l.tilesProjected, l.tilesWithSurvivors) << camera;
    EXPECT_LT(l.tilesProjected, l.tilesWithContent) << camera << ": some tiles with geometry reflect in nothing";
    EXPECT_TRUE(identical(render(f, pose, "1", "1", "tiles").reflection, render(f, pose, "1", "0", "tiles").reflection))
        << camera << ": the per-tile survivor counts differ";
}

TEST(PprTiles, ProjectionRunsOnlyWhereAReflectorCanBeReached) {
    {
        GpuFixture f;  // 15 reflectors: tested one by one
        for (const char* camera : {"overview", "stairs", "normalmap"}) expectReachListsTheTilesWithSurvivors(f, camera, true);
        EXPECT_EQ(f.ctx->validationErrors(), 0u);
    }
    GpuFixture f(scene::makeStressScene(256));  // beyond kPprReachPerReflector: one summary per plane
    expectReachListsTheTilesWithSurvivors(f, "reflective_25", false);
    EXPECT_EQ(f.ctx->validationErrors(), 0u);
}

// PPR's largest frame (4096² = 65 536 tiles) at one workgroup per tile needs more workgroups than a
// dispatch row holds on every device: the reach pass lays them out in rows and still lists exactly
// the tiles with survivors.
// Classification lays its workgroups out in rows the same way (tileGroupGrid): at its widest it
// finds the same tiles as at one invocation per tile.
TEST(PprTiles, ReachCoversTheLargestFrameAtOneTilePerWorkgroup) {
    GpuFixture f;
    f.headless->setTechnique("ppr");
    f.headless->settings().set("reach_threads", std::to_string(passes::kReachThreadChoices.back()));
    f.headless->settings().set("classify_threads", std::to_string(passes::kClassifyThreadChoices.back()));
    const app::CaptureResult r = f.headless->capture(f.camera("overview"), {gpu::kPprMaxExtent, gpu::kPprMaxExtent}, 1, false, false);
    ASSERT_TRUE(r.pprStats);
    std::printf("4096x4096: %u with content, %u with survivors, %u projected\n", r.pprStats->tilesWithContent, r.pprStats->tilesWithSurvivors,
                r.pprStats->tilesProjected);
    EXPECT_GT(r.pprStats->tilesWithSurvivors, 0u);
    EXPECT_EQ(r.pprStats->tilesProjected, r.pprStats->tilesWithSurvivors);
    f.headless->settings().set("classify_threads", std::to_string(passes::kClassifyThreadChoices.front()));
    const app::CaptureResult narrow = f.headless->capture(f.camera("overview"), {gpu::kPprMaxExtent, gpu::kPprMaxExtent}, 1, false, false);
    ASSERT_TRUE(narrow.pprStats);
    for (uint32_t c = 0; c < gpu::kTileClassCount; ++c)
        EXPECT_EQ(r.pprStats->dispatch[c].x, narrow.pprStats->dispatch[c].x) << "tile class " << c;
    EXPECT_GT(r.pprStats->dispatch[gpu::kTileClassPlanar].x, 0u);
    EXPECT_EQ(f.ctx->validationErrors(), 0u);
}

TEST(PprTiles, IndirectArgumentsCountTheReflectiveTiles) {
    GpuFixture f;
    // Looking up at the sky above the courtyard: no reflector pixel on screen.
    scene::CameraPose sky = f.camera("overview");
    sky.pitchDeg = 80.0f;
    const Frame none = render(f, sky, "1", "1");
    ASSERT_TRUE(none.capture.pprStats);
    const gpu::TileDispatchArgs planar = none.capture.pprStats->dispatch[gpu::kTileClassPlanar];
    EXPECT_EQ(planar.x, 0u) << "no reflective pixel: zero reflection workgroups";
    EXPECT_EQ(planar.y, 1u);
    EXPECT_EQ(planar.z, 1u);
    EXPECT_EQ(reflectedPixels(none.reflection), 0u);

    const Frame some = render(f, f.camera("puddles"), "1", "1");
    ASSERT_TRUE(some.capture.pprStats);
    const uint32_t tiles = gpu::pprTilesCovering(kSize.width) * gpu::pprTilesCovering(kSize.height);
    EXPECT_GT(some.capture.pprStats->dispatch[gpu::kTileClassPlanar].x, 0u);
    EXPECT_LT(some.capture.pprStats->dispatch[gpu::kTileClassPlanar].x, tiles);
    EXPECT_EQ(f.ctx->validationErrors(), 0u);
}

TEST(PprTiles, ReflectorsAboveTheBudgetWarnAndStillRender) {
    GpuFixture f(scene::makeStressScene(gpu::kPprMaxReflectors + 1));
    EXPECT_NE(f.renderer->reflectorWarning().find("1025 reflectors exceed PPR's budget of 1024"), std::string::npos)
        << f.renderer->reflectorWarning();
    const Frame fr = render(f, f.camera("overview"), "1", "1");
    EXPECT_EQ(fr.capture.warning, f.renderer->reflectorWarning());
    EXPECT_GT(reflectedPixels(fr.reflection), 100u);
    EXPECT_GT(lumaStdDev(fr.capture.image), 5.0);
    EXPECT_EQ(f.ctx->validationErrors(), 0u);
}

TEST(PprTilesCli, ReportHoldsTileCountsAndTheBudgetWarning) {
    const auto dir = tempDir("tiles-cli");
    const RunResult r = runPpr("capture --scene stress:1025 --camera overview --size 160x90 --frames 1 --validation --out " + dir.string());
    EXPECT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("ppr: warning: 1025 reflectors exceed PPR's budget of 1024"), std::string::npos) << r.output;
    const nlohmann::json report = nlohmann::json::parse(std::ifstream(dir / "report.json"));
    EXPECT_EQ(report["ppr"]["reflectors_projected"], 1024);
    EXPECT_GT(report["ppr"]["tiles_planar"].get<int>(), 0);
    EXPECT_GT(report["ppr"]["reflector_tile_pairs"].get<int>(), 0);
    EXPECT_EQ(report["warnings"].size(), 1u);
    EXPECT_EQ(report["validation_errors"], 0);
}

TEST(PprBenchCli, WritesTablesAndPlot) {
    const auto dir = tempDir("bench-cli");
    const RunResult r = runPpr("bench --size 96x54 --frames 1 --warmup 0 --validation --out " + dir.string());
    EXPECT_EQ(r.exitCode, 0) << r.output;
    // The progress line: every technique but none + 12 reflector + 6 coverage configurations.
    const size_t techniques = app::techniqueTable().size() - 1;
    const std::string last = std::to_string(techniques + 18);
    EXPECT_NE(r.output.find("ppr bench [" + last + "/" + last + "]"), std::string::npos) << r.output;
    const nlohmann::json bench = nlohmann::json::parse(std::ifstream(dir / "bench.json"));
    EXPECT_EQ(bench["sweeps"]["reflectors"]["rows"].size(), 12u);
    EXPECT_EQ(bench["sweeps"]["coverage"]["rows"].size(), 6u);
    const nlohmann::json& results = bench["techniques"]["results"];
    // Every technique but none; without ray queries raytraced is listed as skipped, with the reason.
    const bool rayQueries = rayQueryMissing().empty();
    EXPECT_EQ(results.size(), techniques - (rayQueries ? 0 : 1));
    for (const std::string& t : app::techniqueNames())
        if (t != "none") EXPECT_EQ(results.contains(t), rayQueries || t != "raytraced") << t;
    if (!rayQueries)
        EXPECT_NE(bench["techniques"]["skipped"].value("raytraced", std::string()).find("VK_KHR_ray_query"), std::string::npos) << bench.dump();
    EXPECT_TRUE(results["ppr"]["psnr_db"].is_number());
    EXPECT_GT(results["ppr"]["gpu_ms"].get<double>(), 0.0);
    EXPECT_TRUE(results["ppr"]["ratio_to_floor"].is_number());
    EXPECT_GT(results["ssr-hiz"]["hiz_build_ms"].get<double>(), 0.0);
    EXPECT_TRUE(bench["techniques"]["slides"]["results"].contains("ssr-hiz"));
    EXPECT_TRUE(std::filesystem::exists(dir / "bench.md"));
    EXPECT_TRUE(std::filesystem::exists(dir / "bench.png"));
    EXPECT_EQ(bench["validation_errors"], 0);
}

// --rounds: every row measured once per round in turn; bench.json keeps each round's values and their
// medians (with two rounds, the mean: a technique's GPU ms is then the mean of its rounds').
TEST(PprBenchCli, RoundsKeepEachRoundsValues) {
    const auto dir = tempDir("bench-rounds");
    const RunResult r = runPpr("bench --size 96x54 --frames 1 --warmup 0 --rounds 2 --sweep techniques --sweep reflectors "
                               "--technique ppr --technique floor --validation --out " + dir.string());
    EXPECT_EQ(r.exitCode, 0) << r.output;
    // planar (the reference), ppr and floor, then 12 reflector configurations, each twice.
    EXPECT_NE(r.output.find("ppr bench [30/30]"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("(round 2/2)"), std::string::npos) << r.output;
    const nlohmann::json bench = nlohmann::json::parse(std::ifstream(dir / "bench.json"));
    EXPECT_EQ(bench["rounds"], 2);
    EXPECT_NE(bench["command"].get<std::string>().find("--rounds 2"), std::string::npos);
    const nlohmann::json& ppr = bench["techniques"]["results"]["ppr"];
    ASSERT_EQ(ppr["gpu_ms_rounds"].size(), 2u) << ppr.dump();
    EXPECT_NEAR(ppr["gpu_ms"].get<double>(), 0.5 * (ppr["gpu_ms_rounds"][0].get<double>() + ppr["gpu_ms_rounds"][1].get<double>()), 1e-9);
    EXPECT_EQ(ppr["ratio_to_floor_rounds"].size(), 2u);
    EXPECT_EQ(ppr["planar_gpu_ms_rounds"].size(), 2u);
    EXPECT_TRUE(ppr["psnr_db"].is_number());  // scored on the last round's images
    for (const nlohmann::json& row : bench["sweeps"]["reflectors"]["rows"]) EXPECT_EQ(row["project_ms_rounds"].size(), 2u) << row.dump();
    std::ifstream md(dir / "bench.md");
    const std::string text((std::istreambuf_iterator<char>(md)), std::istreambuf_iterator<char>());
    EXPECT_NE(text.find("## Rounds"), std::string::npos);
    EXPECT_EQ(bench["validation_errors"], 0);
}

// A technique the device cannot run is said once, not once per round: the progress count still ends
// at its total (simulated: PPR_HIDE_RAY_QUERY=1 hides ray queries, so raytraced is skipped).
TEST(PprBenchCli, RoundsSayASkippedTechniqueOnce) {
    const auto dir = tempDir("bench-rounds-skip");
    rayQueryMissing();  // asked before the variable hides them
    RunResult r;
    {
        const ScopedEnv hidden("PPR_HIDE_RAY_QUERY", "1");
        r = runPpr("bench --size 96x54 --frames 1 --warmup 0 --rounds 2 --sweep techniques --out " + dir.string());
    }
    EXPECT_EQ(r.exitCode, 0) << r.output;
    const size_t techniques = app::techniqueTable().size() - 1;  // every technique but none, planar among them
    const std::string last = std::to_string(2 * techniques - 1);
    EXPECT_NE(r.output.find("ppr bench [" + last + "/" + last + "]"), std::string::npos) << r.output;
    const nlohmann::json bench = nlohmann::json::parse(std::ifstream(dir / "bench.json"));
    EXPECT_TRUE(bench["techniques"]["skipped"].contains("raytraced")) << bench.dump();
    EXPECT_EQ(bench["techniques"]["results"].size(), techniques - 1);
    EXPECT_EQ(bench["techniques"]["results"]["ssr-hiz"]["gpu_ms_rounds"].size(), 2u);
}

}  // namespace
}  // namespace ppr::test
