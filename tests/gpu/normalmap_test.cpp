// Normal maps and the environment fallback (issue: the slides' normal-map approximation): they
// change nothing on flat reflectors, change the normal-mapped ones, and the environment fills
// exactly the pixels that had no reflection. Validation + synchronization validation on.
#include "common/reflection.h"
#include "gpu_test_util.hpp"
#include "metrics/compare_metrics.hpp"

#include <cstring>

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
