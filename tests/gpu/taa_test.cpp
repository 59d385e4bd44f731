// Temporal anti-aliasing (--set taa=1): a still camera converges toward the supersampled reference,
// taa=0 leaves no trace in later frames, and the history resets on resize, technique change and a cut.
#include "gpu_test_util.hpp"

#include "metrics/compare_metrics.hpp"
#include "taa/taa_pass.hpp"

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
}

}  // namespace
}  // namespace ppr::test
