// The reflection probe behind --set fallback_env=1 env_source=probe (app/frame/environment_probe.hpp):
// rendered once however many frames ask for it and never when none does, closer to the ray-traced
// reference than the sky alone over all reflector pixels, and without effect while fallback_env=0.
// Validation + synchronization validation on.
#include "common/reflection.h"
#include "gpu_test_util.hpp"
#include "metrics/compare_metrics.hpp"

#include <cstdio>
#include <cstring>

namespace ppr::test {
namespace {

constexpr VkExtent2D kSize{320, 180};

app::CaptureResult render(GpuFixture& f, const std::string& technique, const std::string& camera, bool fallback, const std::string& source,
                          uint32_t frames = 1) {
    f.headless->setTechnique(technique);
    f.headless->settings().set("fallback_env", fallback ? "1" : "0");
    f.headless->settings().set("env_source", source);
    return f.headless->capture(f.camera(camera), kSize, frames, false, true);
}

bool identical(const app::CaptureResult& a, const app::CaptureResult& b) {
    return a.image.pixels == b.image.pixels && a.reflection.rgba.size() == b.reflection.rgba.size() &&
           std::memcmp(a.reflection.rgba.data(), b.reflection.rgba.data(), a.reflection.rgba.size() * sizeof(float)) == 0;
}

TEST(EnvironmentProbe, RenderedOnceAndOnlyWhenAskedFor) {
    GpuFixture f;
    const app::EnvironmentProbe& probe = f.renderer->environmentProbe();
    render(f, "ppr", "puddles", false, "probe", 2);
    render(f, "ssr-hiz", "puddles", true, "sky", 2);
    EXPECT_EQ(probe.renders(), 0u) << "nothing showed the probe: it costs no render";
    EXPECT_FALSE(probe.stats().has_value());
    const app::CaptureResult first = render(f, "ppr", "puddles", true, "probe", 3);
    render(f, "ssr-hiz", "mirror", true, "probe", 2);
    render(f, "ssr-brute", "normalmap", true, "probe", 2);
    EXPECT_EQ(probe.renders(), 1u) << "seven frames of three techniques on three cameras share one render";
    ASSERT_TRUE(first.environmentProbe.has_value());
    const scene::ProbePlacement& p = first.environmentProbe->placement;
    EXPECT_TRUE(glm::all(glm::greaterThanEqual(p.centre, p.boxMin)) && glm::all(glm::lessThanEqual(p.centre, p.boxMax)));
    EXPECT_EQ(first.environmentProbe->bytes, uint64_t(6) * gpu::kEnvProbeFaceSize * gpu::kEnvProbeFaceSize * 8);
    EXPECT_GT(first.environmentProbe->gpuMs, 0.0);
    EXPECT_EQ(f.ctx->validationErrors(), 0u);
}

TEST(EnvironmentProbe, SourceChangesNothingWithoutTheFallback) {
    GpuFixture f;
    for (const char* technique : {"ppr", "ssr-hiz"}) {
        const app::CaptureResult sky = render(f, technique, "normalmap", false, "sky");
        render(f, technique, "normalmap", true, "probe");  // the probe rendered and bound in between
        const app::CaptureResult probe = render(f, technique, "normalmap", false, "probe");
        EXPECT_TRUE(identical(sky, probe)) << technique;
    }
    EXPECT_EQ(f.renderer->environmentProbe().renders(), 1u);
    EXPECT_EQ(f.ctx->validationErrors(), 0u);
}

// Over every reflector pixel (psnr_reflection_db_all) against the ray-traced reference, on the camera
// whose misses see most of the courtyard's walls (docs/normalmaps.md, "What it gains"). Measured at
// 320x180: ppr sky 18.62 dB, probe 20.93 dB; ssr-hiz 19.44, 22.20 dB.
TEST(EnvironmentProbe, BeatsTheSkyAgainstTheRayTracedReference) {
    PPR_SKIP_WITHOUT_RAY_QUERY();
    GpuFixture f;
    const char* camera = "normalmap";
    const app::FloatImage all = app::allReflectorPixels(render(f, "raytraced", camera, false, "probe").reflection);
    const float exposure = f.headless->settings().values().view.exposure;
    for (const char* technique : {"ppr", "ssr-hiz"}) {
        const double sky = app::scoreReflection(render(f, technique, camera, true, "sky").reflection, all, exposure).psnrDb;
        const double probe = app::scoreReflection(render(f, technique, camera, true, "probe").reflection, all, exposure).psnrDb;
        std::printf("%-8s %s: all reflector pixels, sky %.2f dB, probe %.2f dB\n", technique, camera, sky, probe);
        EXPECT_GT(probe, sky + 1.0) << technique;
    }
    EXPECT_EQ(f.ctx->validationErrors(), 0u);
}

}  // namespace
}  // namespace ppr::test
