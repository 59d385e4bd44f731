// Temporal anti-aliasing (--set taa=1): a still camera converges toward the supersampled reference
// and, counting its history's frames (taa_average=1), stops flickering once it holds the jitter cycle,
// on edges too once a pixel's own spread decides its clip (taa_still_spread=1), on lines thinner than
// a pixel once that spread is the run's range (taa_still_range=1), and on a reflector's rim once a still
// reflection's history is kept whatever its path (taa_still_keep=1);
// taa=0 leaves no trace in later frames, and the history resets on resize, technique change, a cut and
// a switch of taa_still_range;
// every taa_threads width gives the same frames.
#include "gpu_test_util.hpp"

#include "metrics/compare_metrics.hpp"
#include "metrics/temporal_metrics.hpp"
#include "taa/taa_pass.hpp"
#include "taa/taa_threads.hpp"
#include "vk/live_objects.hpp"

#include <algorithm>

namespace ppr::test {
namespace {

constexpr VkExtent2D kSize{320, 180};

bool logHas(const graph::HistoryStore& store, const std::string& reason) {
    const std::string line = std::string("history '") + passes::TaaPass::kHistoryName + "' reset: " + reason;
    const std::vector<std::string>& log = store.resetLog();
    return std::find(log.begin(), log.end(), line) != log.end();
}

TEST(Taa, StillCameraConvergesTowardTheSupersampledReference) {
    GpuFixture f;
    f.headless->setTechnique("ppr");
    const scene::CameraPose cam = f.camera("overview");
    const util::Rgba8Image reference = f.headless->captureSupersampled(cam, kSize, scene::kJitterLength);
    const util::Rgba8Image aliased = f.headless->capture(cam, kSize, 1).image;
    f.headless->settings().set("taa", "1");
    const util::Rgba8Image first = f.headless->capture(cam, kSize, 1).image;
    const util::Rgba8Image resolved = f.headless->capture(cam, kSize, 2 * scene::kJitterLength).image;
    const double aliasedDb = app::imagePsnrDb(aliased, reference), firstDb = app::imagePsnrDb(first, reference);
    const double resolvedDb = app::imagePsnrDb(resolved, reference);
    std::printf("vs 16x supersampled: no AA %.2f dB, TAA first frame %.2f dB, TAA after %u frames %.2f dB\n", aliasedDb, firstDb,
                2 * scene::kJitterLength, resolvedDb);
    // The first TAA frame has no history: one jittered sample, no closer than no AA.
    EXPECT_LT(firstDb, aliasedDb + 1.0);
    EXPECT_GT(resolvedDb, aliasedDb + 2.0);
}

// Frames of one shot of a still camera: the mean change between consecutive frames from frame `from`
// on (the flicker), and the PSNR of the last frame against the supersampled reference.
struct StillShot {
    double flicker = 0.0, lastDb = 0.0;
};
StillShot stillShot(GpuFixture& f, const scene::CameraPose& cam, const util::Rgba8Image& reference, uint32_t frames, uint32_t from) {
    StillShot shot;
    util::Rgba8Image previous;
    for (uint32_t k = 0; k < frames; ++k) {
        util::Rgba8Image image = f.headless->capture(cam, kSize, 1, false, false, k == 0).image;
        if (k > from) shot.flicker += app::meanAbsoluteChange(image, previous) / double(frames - from - 1);
        if (k + 1 == frames) shot.lastDb = app::imagePsnrDb(image, reference);
        previous = std::move(image);
    }
    return shot;
}

// A still planar view with TAA, then again with one setting switched off: each shot's flicker from frame
// kJitterLength + 1 on, and its last frame against the supersampled reference. Prints both.
struct StillShots {
    StillShot on, off;
};
StillShots stillShotsWithAndWithout(const char* camera, const char* setting, uint32_t frames) {
    GpuFixture f;
    f.headless->setTechnique("planar");
    const scene::CameraPose cam = f.camera(camera);
    const util::Rgba8Image reference = f.headless->captureSupersampled(cam, kSize, scene::kJitterLength);
    f.headless->settings().set("taa", "1");
    constexpr uint32_t kFrom = scene::kJitterLength;
    StillShots shots;
    shots.on = stillShot(f, cam, reference, frames, kFrom);
    f.headless->settings().set(setting, "0");
    shots.off = stillShot(f, cam, reference, frames, kFrom);
    std::printf("still %s, frames %u-%u: change %.4f levels (%s=0 %.4f), last frame %.2f dB (%.2f)\n", camera, kFrom + 1, frames - 1,
                shots.on.flicker, setting, shots.off.flicker, shots.on.lastDb, shots.off.lastDb);
    EXPECT_EQ(f.ctx->validationErrors(), 0u);
    return shots;
}

// taa_average=1 gives each of a still pixel's frames an equal share and, once it holds the whole jitter
// cycle, keeps that average: the picture stops changing where the feedback of taa_average=0 kept
// 3-12 % of every new jittered frame. Measured on lavapipe (planar, puddles, 320x180, frames 17-23):
// change 0.041 against 0.350 levels, last frame 40.86 against 37.44 dB (0.061 and 40.53 before
// taa_still_spread).
TEST(Taa, AveragingTheJitterCycleStopsAStillViewFlickering) {
    const StillShots shots = stillShotsWithAndWithout("puddles", "taa_average", scene::kJitterLength + 8);
    EXPECT_LT(shots.on.flicker, 0.5 * shots.off.flicker);
    EXPECT_GT(shots.on.lastDb, shots.off.lastDb + 1.0);
}

// taa_still_spread=1: a still pixel whose frame stays within the spread of its own still run keeps its
// average, where one jittered frame's 3x3 box, wholly on one side of an edge the jitter straddles,
// would clip it and restart the run. Measured on lavapipe (planar, overview, 320x180, frames 17-31):
// change 0.0069 levels against 0.0171, last frame 42.76 against 42.43 dB; with taa_still_range and
// taa_still_keep (2026-12-06) 0.0037 against 0.0163, 42.88 against 42.43 dB.
TEST(Taa, StillSpreadKeepsEdgesTheJitterStraddlesStill) {
    const StillShots shots = stillShotsWithAndWithout("overview", "taa_still_spread", 2 * scene::kJitterLength);
    EXPECT_LT(shots.on.flicker, 0.75 * shots.off.flicker);
    EXPECT_GT(shots.on.lastDb, shots.off.lastDb);
}

// taa_still_range=1: the spread is the range of the run's luma, tested from its first frame: a line
// thinner than a pixel (a doorway's sill, a stair's nosing), which most of the jitter cycle's offsets
// miss, lies outside a few frames' variance and kept restarting its run. Measured on lavapipe (planar,
// puddles, 320x180, frames 17-31): change 0.0121 levels against 0.0248, last frame 42.38 against 41.05 dB
// (with taa_still_keep=0: 0.0238 against 0.0345, 41.94 against 40.99).
TEST(Taa, StillRangeKeepsLinesThinnerThanAPixelStill) {
    const StillShots shots = stillShotsWithAndWithout("puddles", "taa_still_range", 2 * scene::kJitterLength);
    EXPECT_LT(shots.on.flicker, 0.8 * shots.off.flicker);
    EXPECT_GT(shots.on.lastDb, shots.off.lastDb);
}

// taa_still_keep=1: on a reflector's rim the jitter alone moves a still pixel's reflected path from one
// surface to another (the far wall mirror's lower edge, seen through the doorway), and the path's depth
// rejected the reflection's history every third frame; kept, the rim stops flickering. Measured on
// lavapipe (planar, puddles, 320x180, frames 17-31): change 0.0121 levels against 0.0238, last frame
// 42.38 against 41.94 dB. (Beside a moving draw's reflection the depth still decides:
// gpu.Animation.ReflectionHistoryFollowsTheMovingObject.)
TEST(Taa, StillKeepHoldsARimReflectionThroughTheJitterCycle) {
    const StillShots shots = stillShotsWithAndWithout("puddles", "taa_still_keep", 2 * scene::kJitterLength);
    EXPECT_LT(shots.on.flicker, 0.75 * shots.off.flicker);
    EXPECT_GT(shots.on.lastDb, shots.off.lastDb);
}

// taa_threads only says how many pixels of a tile each invocation resolves: every width gives the
// same frames, bit for bit, in each of the six resolve shaders (split or whole colour, counted frames
// or not), under camera motion, with the bobbing ball moving and at a size whose last tiles are
// partial. Below 256 the frame's resolve slides each pixel's 3×3 window down its column (256 reads all
// nine), so this also checks the slide. One pipeline per width and shader, made once.
TEST(Taa, EveryWidthGivesTheSameFrames) {
    GpuFixture f;
    f.headless->setTechnique("ppr");
    f.headless->settings().set("taa", "1");
    constexpr VkExtent2D kOdd{333, 187};
    constexpr uint32_t kFrames = 6;
    const scene::CameraPose start = f.camera("puddles");
    const auto shot = [&] {
        std::vector<std::vector<uint8_t>> frames;
        for (uint32_t k = 0; k < kFrames; ++k) {
            scene::CameraPose pose = start;
            pose.position.x += 0.03f * float(k);  // a strafe: the histories are fetched between texels
            f.headless->setSceneTime(0.1 * k);
            frames.push_back(f.headless->capture(pose, kOdd, 1, false, false, k == 0).image.pixels);
        }
        return frames;
    };
    for (const auto& [split, average] : {std::pair{"1", "1"}, std::pair{"0", "1"}, std::pair{"1", "0"}, std::pair{"0", "0"}}) {
        f.headless->settings().set("taa_split", split);
        f.headless->settings().set("taa_average", average);
        const std::string variant = std::string("taa_split=") + split + " taa_average=" + average;
        f.headless->settings().set("taa_threads", std::to_string(passes::kTaaThreadChoices.front()));
        const std::vector<std::vector<uint8_t>> reference = shot();
        for (uint32_t width : passes::kTaaThreadChoices) {
            f.headless->settings().set("taa_threads", std::to_string(width));
            const std::vector<std::vector<uint8_t>> frames = shot();
            for (uint32_t k = 0; k < kFrames; ++k)
                EXPECT_EQ(frames[k], reference[k]) << variant << ", taa_threads=" << width << ": frame " << k << " differs";
        }
    }
    f.headless->setSceneTime(std::nullopt);
    f.headless->settings().set("taa_threads", "auto");
    const int64_t pipelines = vk::liveObjects().pipelines;
    shot();
    EXPECT_EQ(vk::liveObjects().pipelines, pipelines);  // every width's pipelines were made once, above
    EXPECT_EQ(f.ctx->validationErrors(), 0u);
}

// taa_still_spread=0 costs what the resolves cost before the spread: no moments image is kept, read or
// written (a stand-in is bound), and the frames are those of that build (docs/temporal.md, Cost).
TEST(Taa, StillSpreadOffKeepsNoMomentsImage) {
    GpuFixture f;
    f.headless->setTechnique("ppr");
    f.headless->settings().set("taa", "1");
    f.headless->settings().set("taa_still_spread", "0");
    const scene::CameraPose cam = f.camera("overview");
    const graph::HistoryStore& store = f.renderer->executor().history();
    f.headless->capture(cam, kSize, 3);
    EXPECT_TRUE(store.contains(passes::TaaPass::kSamplesName));
    EXPECT_FALSE(store.contains(passes::TaaPass::kSpreadName));
    EXPECT_FALSE(store.contains(passes::TaaPass::kReflectionSpreadName));
    f.headless->settings().set("taa_still_spread", "1");
    f.headless->capture(cam, kSize, 3);
    EXPECT_TRUE(store.contains(passes::TaaPass::kSpreadName));
    EXPECT_TRUE(store.contains(passes::TaaPass::kReflectionSpreadName));
    EXPECT_EQ(f.ctx->validationErrors(), 0u);
}

TEST(Taa, OffLeavesNoTraceInLaterFrames) {
    GpuFixture f;
    f.headless->setTechnique("ppr");
    const scene::CameraPose cam = f.camera("puddles");
    const util::Rgba8Image before = f.headless->capture(cam, kSize, 3).image;
    f.headless->settings().set("taa", "1");
    const util::Rgba8Image withTaa = f.headless->capture(cam, kSize, 5).image;
    f.headless->settings().set("taa", "0");
    const util::Rgba8Image after = f.headless->capture(cam, kSize, 3).image;
    EXPECT_NE(withTaa.pixels, before.pixels);  // TAA did change the picture...
    EXPECT_EQ(after.pixels, before.pixels);    // ...and switched off, no jitter or history remains
}

TEST(Taa, HistoryResetsOnResizeTechniqueChangeAndCut) {
    GpuFixture f;
    f.headless->setTechnique("ppr");
    f.headless->settings().set("taa", "1");
    const scene::CameraPose cam = f.camera("overview");
    const graph::HistoryStore& store = f.renderer->executor().history();
    f.headless->capture(cam, kSize, 3);
    for (const char* name : passes::TaaPass::kHistoryNames) EXPECT_TRUE(store.contains(name)) << name;  // taa_average=1 counts frames
    ASSERT_TRUE(store.contains(passes::TaaPass::kHistoryName));
    EXPECT_TRUE(store.status(passes::TaaPass::kHistoryName)->previousValid);
    EXPECT_FALSE(logHas(store, "resize"));
    f.headless->capture(cam, {256, 144}, 3);
    EXPECT_TRUE(logHas(store, "resize"));
    EXPECT_TRUE(logHas(store, "camera cut"));  // each capture starts a new shot
    EXPECT_FALSE(logHas(store, "technique change"));
    f.headless->setTechnique("ssr-hiz");
    f.headless->capture(cam, {256, 144}, 3);
    EXPECT_TRUE(logHas(store, "technique change"));
    EXPECT_TRUE(store.status(passes::TaaPass::kHistoryName)->previousValid);  // rebuilt since
    // The spread images hold a range or moments: switching taa_still_range restarts the histories.
    EXPECT_FALSE(logHas(store, "taa_still_range change"));
    f.headless->settings().set("taa_still_range", "0");
    f.headless->capture(cam, {256, 144}, 3);
    EXPECT_TRUE(logHas(store, "taa_still_range change"));
}

}  // namespace
}  // namespace ppr::test
