// The screen-space ray-marched baselines against the planar ground truth on every named camera of the
// default scene, and against each other, with validation + synchronization validation on.
#include "common/reflection.h"
#include "metrics/compare_metrics.hpp"
#include "gpu_test_util.hpp"
#include "tonemap/tonemap.h"

#include <algorithm>
#include <cstring>
#include <map>

namespace ppr::test {
namespace {

constexpr VkExtent2D kSize{640, 360};  // as the PPR tests, so the scores compare
const char* const kCameras[] = {"overview", "puddles", "grazing", "stairs", "mirror"};
const char* const kSsrTechniques[] = {"ssr-brute", "ssr-lowq", "ssr-hiz", "ssr-linear"};

app::FloatImage renderReflection(GpuFixture& f, const std::string& technique, const std::string& camera, util::Rgba8Image* final = nullptr) {
    f.headless->setTechnique(technique);
    app::CaptureResult r = f.headless->capture(f.camera(camera), kSize, 1, false, true);
    if (final) *final = std::move(r.image);
    return std::move(r.reflection);
}

// Thresholds: measured on lavapipe (Mesa 25.0.7) at 640x360 with the default ssr_* settings, rounded
// down by about 1 dB (coverage by 0.02). The measured values are in docs/quality.md.
struct Expected {
    double reflectionDb, coverage;
};
const std::map<std::string, std::map<std::string, Expected>> kExpected = {
    // Glass panels are transparent and drawn after the G-buffer: no screen-space technique reflects in
    // them, and they are not among these pixels.
    // measured reflection dB / coverage:  overview 20.47/0.9970  puddles 23.99/0.9938  grazing 25.76/0.9999
    //                                     stairs 22.77/0.9978    mirror 22.48/0.9978
    {"ssr-brute", {{"overview", {19.4, 0.97}}, {"puddles", {22.9, 0.97}}, {"grazing", {24.7, 0.97}}, {"stairs", {21.7, 0.97}}, {"mirror", {21.4, 0.97}}}},
    // 9.14/0.6689  13.86/0.8545  18.61/0.9597  11.45/0.8984  16.50/0.9154
    {"ssr-lowq", {{"overview", {8.1, 0.64}}, {"puddles", {12.8, 0.83}}, {"grazing", {17.6, 0.94}}, {"stairs", {10.4, 0.87}}, {"mirror", {15.5, 0.89}}}},
    // 20.44/0.9970  24.18/0.9946  25.79/0.9999  22.89/0.9983  22.48/0.9978
    {"ssr-hiz", {{"overview", {19.4, 0.97}}, {"puddles", {23.1, 0.97}}, {"grazing", {24.7, 0.97}}, {"stairs", {21.8, 0.97}}, {"mirror", {21.4, 0.97}}}},
    // 16.71/0.9766  18.02/0.9668  23.43/0.9946  19.52/0.9919  19.97/0.9475
    {"ssr-linear", {{"overview", {15.7, 0.95}}, {"puddles", {17.0, 0.94}}, {"grazing", {22.4, 0.97}}, {"stairs", {18.5, 0.97}}, {"mirror", {18.9, 0.92}}}},
};

TEST(SsrVsPlanar, EveryTechniqueRendersEveryCameraAndScores) {
    GpuFixture f;
    const float exposure = static_cast<float>(f.headless->settings().number("exposure"));
    std::map<std::string, double> meanDb;
    for (const char* camera : kCameras) {
        const app::FloatImage ref = renderReflection(f, "planar", camera);
        for (const char* technique : kSsrTechniques) {
            util::Rgba8Image final;
            const app::FloatImage reflection = renderReflection(f, technique, camera, &final);
            EXPECT_GT(lumaStdDev(final), 10.0) << technique << " " << camera << ": the frame is not blank";
            const app::ReflectionScore s = app::scoreReflection(reflection, ref, exposure);
            std::printf("%-10s %-9s psnr_reflection_db %6.2f  coverage %.4f\n", technique, camera, s.psnrDb, s.coverage);
            const Expected& e = kExpected.at(technique).at(camera);
            EXPECT_GE(s.psnrDb, e.reflectionDb) << technique << " " << camera;
            EXPECT_GE(s.coverage, e.coverage) << technique << " " << camera;
            meanDb[technique] += s.psnrDb / std::size(kCameras);
        }
    }
    // Pixel-granular marching is the family's reference quality. ssr-hiz walks the same pixels where the
    // hierarchy cannot rule them out, so it may tie (float rounding of the two walks: measured within
    // 0.2 dB, mean 23.16 against 23.09); the others march coarser and must score lower.
    EXPECT_LT(meanDb["ssr-lowq"], meanDb["ssr-brute"]);
    EXPECT_LT(meanDb["ssr-linear"], meanDb["ssr-brute"]);
    EXPECT_LE(meanDb["ssr-hiz"], meanDb["ssr-brute"] + 0.25);
    std::printf("mean psnr_reflection_db: brute %.2f  lowq %.2f  hiz %.2f  linear %.2f\n", meanDb["ssr-brute"], meanDb["ssr-lowq"],
                meanDb["ssr-hiz"], meanDb["ssr-linear"]);
    EXPECT_EQ(f.ctx->validationErrors(), 0u);
}

// How a technique's reflection agrees with ssr-brute's.
struct Agreement {
    uint64_t bruteHits = 0, techniqueHits = 0, allHit = 0;
    double meanAbsDiff = 0.0;  // display units [0, 1], mean over the pixels every image hits and rgb
    double recall() const { return bruteHits ? double(techniqueHits) / double(bruteHits) : 1.0; }
};

Agreement agreement(const app::FloatImage& brute, const app::FloatImage& technique, const std::vector<const app::FloatImage*>& all,
                    float exposure) {
    Agreement a;
    double sum = 0.0;
    auto hit = [](const app::FloatImage& img, size_t i) { return img.rgba[i * 4 + 3] == gpu::kReflectionHit; };
    auto display = [&](const app::FloatImage& img, size_t i) {
        return gpu::displayFromRadiance(glm::vec3(img.rgba[i * 4], img.rgba[i * 4 + 1], img.rgba[i * 4 + 2]), exposure);
    };
    for (size_t i = 0; i < size_t(brute.width) * brute.height; ++i) {
        if (!hit(brute, i)) continue;
        ++a.bruteHits;
        a.techniqueHits += hit(technique, i);
        if (!std::all_of(all.begin(), all.end(), [&](const app::FloatImage* img) { return hit(*img, i); })) continue;
        ++a.allHit;
        const glm::vec3 d = glm::abs(display(brute, i) - display(technique, i));
        sum += (d.x + d.y + d.z) / 3.0;
    }
    a.meanAbsDiff = a.allHit ? sum / double(a.allHit) : 0.0;
    return a;
}

// Measured at 640x360 (recall of brute's hits, mean |display difference| where all three hit), with
// the tolerances set a little above. ssr-hiz walks the pixels ssr-brute walks, skipping only cells the
// hierarchy rules out, so it agrees almost exactly; ssr-lowq's 64 px stride steps over thin objects
// and its binary search may settle on a later crossing.
struct Tolerance {
    double minRecall, maxMeanAbsDiff;
};
const std::map<std::string, std::map<std::string, Tolerance>> kAgreement = {
    // measured: overview 0.7002/0.0560  puddles 0.8009/0.0254  grazing 0.9405/0.0209  stairs 0.8967/0.0982
    //           mirror 0.8504/0.0219
    {"ssr-lowq", {{"overview", {0.67, 0.066}}, {"puddles", {0.77, 0.035}}, {"grazing", {0.91, 0.03}}, {"stairs", {0.87, 0.11}}, {"mirror", {0.82, 0.035}}}},
    // measured: recall 0.9999-1.0000, mean difference 0.0001-0.0005
    {"ssr-hiz", {{"overview", {0.999, 0.002}}, {"puddles", {0.999, 0.002}}, {"grazing", {0.999, 0.002}}, {"stairs", {0.999, 0.002}}, {"mirror", {0.999, 0.002}}}},
};

TEST(SsrFamily, LowQualityAndHierarchicalAgreeWithBruteForceWhereAllThreeHit) {
    GpuFixture f;
    const float exposure = static_cast<float>(f.headless->settings().number("exposure"));
    for (const char* camera : kCameras) {
        const app::FloatImage brute = renderReflection(f, "ssr-brute", camera);
        const app::FloatImage lowq = renderReflection(f, "ssr-lowq", camera);
        const app::FloatImage hiz = renderReflection(f, "ssr-hiz", camera);
        for (const auto& [name, img] : {std::pair{"ssr-lowq", &lowq}, std::pair{"ssr-hiz", &hiz}}) {
            const Agreement a = agreement(brute, *img, {&lowq, &hiz}, exposure);
            std::printf("%-9s %-9s recall %.4f  all three hit %llu  mean |display difference| %.4f\n", name, camera, a.recall(),
                        static_cast<unsigned long long>(a.allHit), a.meanAbsDiff);
            ASSERT_GT(a.allHit, 500u) << camera;
            const Tolerance& t = kAgreement.at(name).at(camera);
            EXPECT_GE(a.recall(), t.minRecall) << name << " " << camera;
            EXPECT_LE(a.meanAbsDiff, t.maxMeanAbsDiff) << name << " " << camera;
        }
    }
    EXPECT_EQ(f.ctx->validationErrors(), 0u);
}

// Indirect dispatch over the tile lists shades exactly the pixels the whole-screen pass shades.
TEST(SsrFamily, IndirectAndWholeScreenDispatchAreBitIdentical) {
    GpuFixture f;
    for (const char* camera : {"puddles", "mirror"}) {
        for (const char* technique : {"ssr-brute", "ssr-lowq", "ssr-hiz", "ssr-linear", "ppr"}) {
            f.headless->settings().set("indirect", "1");
            const app::FloatImage indirect = renderReflection(f, technique, camera);
            f.headless->settings().set("indirect", "0");
            const app::FloatImage whole = renderReflection(f, technique, camera);
            f.headless->settings().set("indirect", "1");
            ASSERT_EQ(indirect.rgba.size(), whole.rgba.size());
            EXPECT_EQ(std::memcmp(indirect.rgba.data(), whole.rgba.data(), whole.rgba.size() * sizeof(float)), 0)
                << technique << " " << camera << " (ppr: with its fallback)";
        }
    }
    EXPECT_EQ(f.ctx->validationErrors(), 0u);
}

// hiz_skip: crossing an 8x8 cell the ray stays behind in one step leaves every reflection where the
// pixel-by-pixel walk puts it (bit for bit, ssr-hiz and PPR's fallback, at every hiz_threads and with
// PPR's reach pass storing the cells), and it does skip: under a step cap too small for the walk,
// the skipping march reaches more hits.
TEST(SsrFamily, HierarchySkipBehindObjectsChangesNoReflection) {
    GpuFixture f;
    for (const char* camera : kCameras)
        for (const char* technique : {"ssr-hiz", "ppr"})
            for (const char* threads : {"16", "256"}) {
                f.headless->settings().set("hiz_threads", threads);
                f.headless->settings().set("hiz_skip", "1");
                const app::FloatImage skip = renderReflection(f, technique, camera);
                f.headless->settings().set("hiz_skip", "0");
                const app::FloatImage walk = renderReflection(f, technique, camera);
                ASSERT_EQ(skip.rgba.size(), walk.rgba.size());
                EXPECT_EQ(std::memcmp(skip.rgba.data(), walk.rgba.data(), walk.rgba.size() * sizeof(float)), 0)
                    << technique << " " << camera << " hiz_threads=" << threads;
            }
    f.headless->settings().set("hiz_threads", "auto");
    f.headless->settings().set("ssr_steps", "24");
    size_t more = 0, fewer = 0;
    for (const char* camera : kCameras) {
        f.headless->settings().set("hiz_skip", "1");
        const app::FloatImage skip = renderReflection(f, "ssr-hiz", camera);
        f.headless->settings().set("hiz_skip", "0");
        const app::FloatImage walk = renderReflection(f, "ssr-hiz", camera);
        for (size_t i = 0; i < size_t(walk.width) * walk.height; ++i) {
            const bool skipHit = skip.rgba[i * 4 + 3] == gpu::kReflectionHit, walkHit = walk.rgba[i * 4 + 3] == gpu::kReflectionHit;
            more += skipHit && !walkHit;
            fewer += walkHit && !skipHit;
        }
    }
    std::printf("ssr_steps=24: hits only with the skip %zu, only without %zu\n", more, fewer);
    EXPECT_GT(more, 100u);
    EXPECT_LT(fewer, more / 10);
    f.headless->settings().set("ssr_steps", "4096");
    f.headless->settings().set("hiz_skip", "1");
    EXPECT_EQ(f.ctx->validationErrors(), 0u);
}

// Pixel masks from the debug views: reflector-rectangle pixels (debug=reflectors tints them) and
// pixels whose material is flagged reflective (debug=roughness shows the flag in blue).
std::vector<bool> otherReflectivePixels(GpuFixture& f, const std::string& camera) {
    auto finalWith = [&](const std::string& debug) {
        f.headless->settings().set("debug", debug);
        f.headless->setTechnique("none");
        util::Rgba8Image img = f.headless->capture(f.camera(camera), kSize, 1).image;
        f.headless->settings().set("debug", "none");
        return img;
    };
    const util::Rgba8Image plain = finalWith("none"), ids = finalWith("reflectors"), material = finalWith("roughness");
    std::vector<bool> mask(size_t(kSize.width) * kSize.height);
    for (size_t i = 0; i < mask.size(); ++i) {
        const bool reflector = std::memcmp(&plain.pixels[i * 4], &ids.pixels[i * 4], 3) != 0;
        const bool reflective = material.pixels[i * 4 + 2] > 128;
        mask[i] = reflective && !reflector;
    }
    return mask;
}

TEST(PprFallback, ShadesTheNonPlanarReflectiveSurfacesOnly) {
    GpuFixture f;
    for (const char* camera : {"grazing", "puddles"}) {
        const std::vector<bool> other = otherReflectivePixels(f, camera);
        const size_t otherCount = std::count(other.begin(), other.end(), true);
        ASSERT_GT(otherCount, 300u) << camera << ": the chrome sphere and the steel post should be in view";

        f.headless->settings().set("fallback", "none");
        util::Rgba8Image finalWithout, finalWith;
        const app::FloatImage without = renderReflection(f, "ppr", camera, &finalWithout);
        f.headless->settings().set("fallback", "ssr");
        const app::FloatImage with = renderReflection(f, "ppr", camera, &finalWith);
        const app::FloatImage hiz = renderReflection(f, "ssr-hiz", camera);

        size_t hits = 0;
        for (size_t i = 0; i < other.size(); ++i) {
            const float* a = &without.rgba[i * 4];
            const float* b = &with.rgba[i * 4];
            if (!other[i]) {
                ASSERT_EQ(std::memcmp(a, b, 4 * sizeof(float)), 0) << camera << ": pixel " << i << " is not the fallback's";
                ASSERT_EQ(std::memcmp(&finalWithout.pixels[i * 4], &finalWith.pixels[i * 4], 4), 0) << camera << ": pixel " << i;
                continue;
            }
            ASSERT_EQ(a[3], gpu::kReflectionNone) << camera << ": PPR alone reflects nothing off its rectangles";
            // The fallback is ssr-hiz over the non-planar tiles: the same value the technique gives.
            ASSERT_EQ(std::memcmp(b, &hiz.rgba[i * 4], 4 * sizeof(float)), 0) << camera << ": pixel " << i;
            hits += b[3] == gpu::kReflectionHit;
        }
        std::printf("%-8s fallback hits %zu of %zu non-planar reflective pixels\n", camera, hits, otherCount);
        // Measured 0.39 (grazing: many rays off the chrome sphere leave the screen) and 0.87 (puddles).
        EXPECT_GT(double(hits) / double(otherCount), 0.3) << camera;
    }
    EXPECT_EQ(f.ctx->validationErrors(), 0u);
}

}  // namespace
}  // namespace ppr::test
