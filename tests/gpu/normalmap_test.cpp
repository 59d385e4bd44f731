// Normal maps and the environment fallback (issue: the slides' normal-map approximation): they
// change nothing on flat reflectors, change the normal-mapped ones, and the environment fills
// exactly the pixels that had no reflection. Validation + synchronization validation on.
#include "common/reflection.h"
#include "ppr_common/tiles.h"
#include "gpu_test_util.hpp"
#include "metrics/compare_metrics.hpp"

#include <cstdio>
#include <cstring>
#include <map>

namespace ppr::test {
namespace {

constexpr VkExtent2D kSize{320, 180};
const char* const kFlatCameras[] = {"overview", "puddles", "grazing", "stairs", "mirror", "glass"};

app::FloatImage reflection(GpuFixture& f, const std::string& technique, const std::string& camera, const std::string& normalMap,
                           bool environment) {
    f.headless->setTechnique(technique);
    f.headless->settings().set("normalmap", normalMap);
    f.headless->settings().set("fallback_env", environment ? "1" : "0");
    app::CaptureResult r = f.headless->capture(f.camera(camera), kSize, 1, false, true);
    return std::move(r.reflection);
}

size_t differingPixels(const app::FloatImage& a, const app::FloatImage& b) {
    size_t n = 0;
    for (size_t i = 0; i < a.rgba.size(); i += 4) n += std::memcmp(&a.rgba[i], &b.rgba[i], 4 * sizeof(float)) != 0;
    return n;
}

TEST(NormalMaps, FlatReflectorsAreExactlyAsWithoutNormalMaps) {
    GpuFixture f;
    for (const char* camera : kFlatCameras)
        for (const char* technique : {"ppr", "ssr-brute"}) {
            const app::FloatImage off = reflection(f, technique, camera, "off", false);
            for (const char* mode : {"approx", "raymarch"})
                EXPECT_EQ(differingPixels(off, reflection(f, technique, camera, mode, false)), 0u) << technique << " " << camera << " " << mode;
        }
    EXPECT_EQ(f.ctx->validationErrors(), 0u);
}

TEST(NormalMaps, ChangeTheNormalMappedReflectors) {
    GpuFixture f;
    f.headless->settings().set("fallback", "ssr");  // the approximation alone: PPR's holes stay holes
    const app::FloatImage off = reflection(f, "ppr", "normalmap", "off", false);
    const app::FloatImage approx = reflection(f, "ppr", "normalmap", "approx", false);
    const app::FloatImage raymarch = reflection(f, "ppr", "normalmap", "raymarch", false);
    // The corner's three reflectors cover a large part of the view; the mapped normals move most of them.
    EXPECT_GT(differingPixels(off, approx), 1000u);
    EXPECT_GT(differingPixels(off, raymarch), 200u);
    EXPECT_GT(differingPixels(approx, raymarch), 100u);
    // Every pixel that changed is a reflector pixel PPR had data for: no reflection appears or vanishes.
    for (size_t i = 0; i < off.rgba.size(); i += 4) {
        EXPECT_EQ(off.rgba[i + 3], raymarch.rgba[i + 3]) << "pixel " << i / 4;
        EXPECT_EQ(off.rgba[i + 3], approx.rgba[i + 3]) << "pixel " << i / 4;
    }
    // SSR reflects about the mapped normal too.
    EXPECT_GT(differingPixels(reflection(f, "ssr-brute", "normalmap", "off", false), reflection(f, "ssr-brute", "normalmap", "raymarch", false)),
              500u);
    EXPECT_EQ(f.ctx->validationErrors(), 0u);
}

TEST(EnvironmentFallback, FillsExactlyThePixelsWithoutAReflection) {
    GpuFixture f;
    for (const char* technique : {"ppr", "ssr-hiz", "ssr-brute"})
        for (const char* camera : {"puddles", "normalmap"}) {
            const app::FloatImage off = reflection(f, technique, camera, "raymarch", false);
            const app::FloatImage on = reflection(f, technique, camera, "raymarch", true);
            size_t filled = 0, faded = 0;
            for (size_t i = 0; i < off.rgba.size(); i += 4) {
                const float a0 = off.rgba[i + 3], a1 = on.rgba[i + 3];
                if (a0 == gpu::kReflectionNone) {
                    // Nothing before: the environment now, or still nothing (not a reflective pixel).
                    EXPECT_TRUE(a1 == gpu::kReflectionNone || a1 == gpu::kReflectionEnvironment) << technique << " " << camera << " pixel " << i / 4 << " alpha " << a1 << " rgb " << on.rgba[i];
                    filled += a1 == gpu::kReflectionEnvironment;
                } else {
                    EXPECT_EQ(a1, a0) << technique << " " << camera << " pixel " << i / 4;  // a hit stays a hit
                    faded += std::memcmp(&off.rgba[i], &on.rgba[i], 3 * sizeof(float)) != 0;
                }
            }
            EXPECT_GT(filled, 50u) << technique << " " << camera << ": misses show the sky";
            // Only hits near the screen border fade: few of them.
            EXPECT_LT(faded, off.rgba.size() / 4 / 10) << technique << " " << camera;
        }
    EXPECT_EQ(f.ctx->validationErrors(), 0u);
}

}  // namespace
}  // namespace ppr::test

namespace ppr::test {
namespace {

// Against the ray-traced reference (mapped normals) on the normal-mapped camera, over the pixels
// every PPR mode has a reflection for: what the approximation itself gets right, holes aside.
TEST(NormalMaps, ApproximationAgainstTheRayTracedReference) {
    PPR_SKIP_WITHOUT_RAY_QUERY();
    GpuFixture f;
    const app::FloatImage truth = reflection(f, "raytraced", "normalmap", "raymarch", false);
    const float exposure = f.headless->settings().values().view.exposure;
    std::map<std::string, app::FloatImage> modes;
    for (const char* mode : {"off", "approx", "raymarch"}) modes[mode] = reflection(f, "ppr", "normalmap", mode, false);
    f.headless->settings().set("normal_refine", "0");  // the slides' four taps, no search
    modes["taps"] = reflection(f, "ppr", "normalmap", "raymarch", false);
    f.headless->settings().set("normal_refine", "walk");  // the search before the surfaces' planes
    modes["walk"] = reflection(f, "ppr", "normalmap", "raymarch", false);
    f.headless->settings().set("normal_refine", "1");
    app::FloatImage mask = truth;
    for (size_t i = 0; i < mask.rgba.size(); i += 4)
        if (modes["off"].rgba[i + 3] == gpu::kReflectionNone) mask.rgba[i + 3] = gpu::kReflectionNone;
    std::map<std::string, double> db;
    for (const auto& [mode, image] : modes) {
        const app::ReflectionScore s = app::scoreReflection(image, mask, exposure);
        db[mode] = s.psnrDb;
        std::printf("normalmap=%-8s %6.2f dB over %llu normal-mapped pixels with a PPR reflection\n", mode.c_str(), s.psnrDb,
                    static_cast<unsigned long long>(s.maskPixels));
        EXPECT_GT(s.maskPixels, 800u);
    }
    const app::ReflectionScore brute = app::scoreReflection(reflection(f, "ssr-brute", "normalmap", "raymarch", false), mask, exposure);
    std::printf("ssr-brute          %6.2f dB over the same pixels\n", brute.psnrDb);
    // Measured at 320x180 (2026-12-06): off 24.27, approx 24.45, the slides' taps 24.61, raymarch with
    // the surfaces' planes (normal_refine=1) 26.77, with the walk and bisection 25.79 (2026-11-27; its
    // bisection alone, before the walk past the approximated point: 26.03), ssr-brute 24.16 dB
    // (before the minified footprint of 2026-11-26, on the same host: 24.14, 24.21, 24.47 for the
    // taps, 24.16).
    EXPECT_GT(db["approx"], db["off"]) << "reflecting about the mapped normal beats the flat mirror";
    EXPECT_GT(db["taps"], db["approx"]) << "the taps fix the approximation's disocclusions";
    EXPECT_GT(db["walk"], db["taps"] + 0.5) << "the walk and bisection find where the ray meets the depth buffer";
    EXPECT_GT(db["raymarch"], db["walk"]) << "the surfaces' planes find it exactly on flat faces, not within a step";
    EXPECT_GT(db["raymarch"], brute.psnrDb - 1.0) << "within 1 dB of brute force where PPR has a reflection";
    EXPECT_EQ(f.ctx->validationErrors(), 0u);
}

// The "PPR raymarch within 1 dB of ssr-brute", as composited over every pixel the ray
// tracer scores on the normal-mapped camera (PPR's holes marched, as by default). The slides' taps
// alone fall short there: on the wall mirror their taken point is free space in front of the floor
// tiles the mapped rays meet, and the approximated point itself often lies in front of them.
TEST(NormalMaps, RefinedRaymarchMatchesBruteForceAsComposited) {
    PPR_SKIP_WITHOUT_RAY_QUERY();
    GpuFixture f;
    auto capture = [&](const std::string& technique) {
        f.headless->setTechnique(technique);
        return f.headless->capture(f.camera("normalmap"), kSize, 1, false, true);
    };
    const app::CaptureResult truth = capture("raytraced");
    const double brute = app::compositedPsnrDb(capture("ssr-brute").image, truth.image, truth.reflection);
    const double refined = app::compositedPsnrDb(capture("ppr").image, truth.image, truth.reflection);
    f.headless->settings().set("normal_refine", "0");
    const double taps = app::compositedPsnrDb(capture("ppr").image, truth.image, truth.reflection);
    f.headless->settings().set("normal_refine", "walk");
    const double walk = app::compositedPsnrDb(capture("ppr").image, truth.image, truth.reflection);
    f.headless->settings().set("normal_refine", "1");
    std::printf("composited against raytraced: ppr %.2f dB, normal_refine=walk %.2f dB, normal_refine=0 %.2f dB, ssr-brute %.2f dB\n",
                refined, walk, taps, brute);
    // Measured at 320x180 (2026-12-06): ppr 41.35, normal_refine=walk 39.62, normal_refine=0 29.48,
    // ssr-brute 35.37 dB.
    EXPECT_GT(refined, brute - 1.0) << "within 1 dB of brute force";
    EXPECT_GT(walk, brute - 1.0) << "within 1 dB of brute force";
    EXPECT_GT(refined, taps + 1.0) << "the surfaces' planes find the crossing";
    EXPECT_GT(walk, taps + 1.0) << "the bisection and the walk past the approximated point find the crossing";
    EXPECT_EQ(f.ctx->validationErrors(), 0u);
}

// fallback=ssr_holes (the default): the SSR fallback also marches PPR's holes on normal-mapped
// reflectors — on the normal-mapped camera the pixels whose mapped ray finds what the flat
// reflection cannot. Every pixel PPR resolved keeps its reflection bit for bit; the holes fill, and
// the score against the ray tracer rises. On flat mirrors nothing changes.
TEST(NormalMaps, HoleFallbackMarchesOnlyPprsHoles) {
    PPR_SKIP_WITHOUT_RAY_QUERY();
    GpuFixture f;
    const app::FloatImage truth = reflection(f, "raytraced", "normalmap", "raymarch", false);
    const float exposure = f.headless->settings().values().view.exposure;
    f.headless->settings().set("fallback", "ssr");
    const app::FloatImage plain = reflection(f, "ppr", "normalmap", "raymarch", false);
    // Every camera but overview, which sees the normal-mapped corner's reflectors from afar (their holes are marched too).
    const char* const flatOnly[] = {"puddles", "grazing", "stairs", "mirror", "glass"};
    std::map<std::string, app::FloatImage> flat;
    for (const char* camera : flatOnly) flat[camera] = reflection(f, "ppr", camera, "raymarch", false);
    f.headless->settings().set("fallback", "ssr_holes");
    const app::FloatImage marched = reflection(f, "ppr", "normalmap", "raymarch", false);
    for (const char* camera : flatOnly)
        EXPECT_EQ(differingPixels(flat[camera], reflection(f, "ppr", camera, "raymarch", false)), 0u) << camera << ": a flat mirror's holes stay";
    size_t filled = 0, holes = 0;
    for (size_t i = 0; i < plain.rgba.size(); i += 4) {
        if (plain.rgba[i + 3] == gpu::kReflectionNone) {
            holes += truth.rgba[i + 3] == gpu::kReflectionHit;  // the ray tracer sees its reflected point on screen
            filled += truth.rgba[i + 3] == gpu::kReflectionHit && marched.rgba[i + 3] == gpu::kReflectionHit;
        } else {
            EXPECT_EQ(std::memcmp(&plain.rgba[i], &marched.rgba[i], 4 * sizeof(float)), 0) << "pixel " << i / 4 << ": PPR's own reflection changed";
        }
    }
    const app::ReflectionScore before = app::scoreReflection(plain, truth, exposure), after = app::scoreReflection(marched, truth, exposure);
    std::printf("holes whose reflected point is on screen %zu, marched %zu; %.2f -> %.2f dB, coverage %.4f -> %.4f\n", holes, filled,
                before.psnrDb, after.psnrDb, before.coverage, after.coverage);
    // Measured at 320x180 (2026-11-27): 43 holes, all marched; 17.25 -> 24.63 dB, coverage 0.9640 -> 1.0000
    // (17.44 -> 25.77 dB since normal_refine; 17.57 -> 26.70 with its planes, 2026-12-06).
    EXPECT_GT(holes, 20u) << "the view should show PPR's holes";
    EXPECT_GE(filled * 10, holes * 9) << "the march finds nearly every hole's reflection";
    EXPECT_GT(after.coverage, before.coverage);
    EXPECT_GT(after.psnrDb, before.psnrDb + 3.0);
    EXPECT_EQ(f.ctx->validationErrors(), 0u);
}

// indirect=1 (the default): ppr.reflect lists the planar tiles that hold a pixel the fallback will
// march (a normal-mapped hole), and ppr.fallback.holes runs on those alone. The reflection is the
// whole-screen march's (indirect=0) bit for bit, with and without the environment; the list is
// shorter than the planar list where some reflectors are flat, empty without normal-mapped
// reflectors, and with normalmap=off there is no holes pass at all.
TEST(NormalMaps, HoleMarchRunsOnlyOnTheTilesThatHoldHoles) {
    GpuFixture f;
    f.headless->setTechnique("ppr");
    auto capture = [&](const char* camera, const char* indirect, const char* env, const char* normalMap) {
        f.headless->settings().set("indirect", indirect);
        f.headless->settings().set("fallback_env", env);
        f.headless->settings().set("normalmap", normalMap);
        return f.headless->capture(f.camera(camera), kSize, 1, false, true);
    };
    for (const char* camera : {"normalmap", "overview"})
        for (const char* env : {"0", "1"}) {
            const app::CaptureResult listed = capture(camera, "1", env, "raymarch");
            const app::CaptureResult whole = capture(camera, "0", env, "raymarch");
            EXPECT_EQ(differingPixels(listed.reflection, whole.reflection), 0u) << camera << " fallback_env=" << env;
            ASSERT_TRUE(listed.pprStats.has_value());
            const gpu::PprFrameStats& s = *listed.pprStats;
            // The march changes something (against fallback=ssr: holes left as PPR left them) where listed.
            f.headless->settings().set("fallback", "ssr");
            const size_t marched = differingPixels(capture(camera, "1", env, "raymarch").reflection, listed.reflection);
            f.headless->settings().set("fallback", "ssr_holes");
            std::printf("%s fallback_env=%s: %u of %u planar tiles listed, %zu pixels changed by the march\n", camera, env,
                        s.tilesWithMappedHoles, s.dispatch[gpu::kTileClassPlanar].x, marched);
            EXPECT_LT(s.tilesWithMappedHoles, s.dispatch[gpu::kTileClassPlanar].x) << camera;
            if (std::string(camera) == "normalmap") EXPECT_GT(marched, 20u) << "the view shows PPR's holes";
            EXPECT_EQ(listed.passMedianMs.count("ppr.fallback.holes"), 1u);
        }
    EXPECT_EQ(capture("stairs", "1", "0", "raymarch").pprStats->tilesWithMappedHoles, 0u) << "no normal maps there";
    const app::CaptureResult off = capture("normalmap", "1", "0", "off");
    EXPECT_EQ(off.pprStats->tilesWithMappedHoles, 0u);
    EXPECT_EQ(off.passMedianMs.count("ppr.fallback.holes"), 0u) << "normalmap=off: no hole to march";
    EXPECT_EQ(f.ctx->validationErrors(), 0u);
}

}  // namespace
}  // namespace ppr::test
