// glTF's emissive term (with KHR_materials_emissive_strength) and vertex colours (COLOR_0) through
// every path that shades a surface: the G-buffer and lighting pass, the shadow map's alpha mask, the
// planar reference's mirrored views and the ray-traced reference's hits. Validation + synchronization
// validation on.
#include "common/reflection.h"
#include "metrics/compare_metrics.hpp"
#include "gpu_test_util.hpp"
#include "tonemap/tonemap.h"

#include <cmath>
#include <set>

namespace ppr::test {
namespace {

constexpr VkExtent2D kSize{320, 180};

app::CaptureResult capture(GpuFixture& f, const std::string& technique, const std::string& camera) {
    f.headless->setTechnique(technique);
    return f.headless->capture(f.camera(camera), kSize, 1, false, true);
}

util::Rgba8Image render(scene::Scene s, const std::string& camera, const std::string& technique = "ppr") {
    GpuFixture f(std::move(s));
    const util::Rgba8Image image = capture(f, technique, camera).image;
    EXPECT_EQ(f.ctx->validationErrors(), 0u);
    return image;
}

// Gives every vertex of the meshes drawn with `material` a colour from `color(position)`.
template <typename ColorOf>
void paintVertices(scene::Scene& s, int material, ColorOf color) {
    std::set<uint32_t> vertices;
    for (scene::Mesh& m : s.meshes) {
        if (m.material != material) continue;
        m.vertexColors = true;
        for (uint32_t i = 0; i < m.indexCount; ++i) vertices.insert(uint32_t(m.vertexOffset) + s.indices[m.firstIndex + i]);
    }
    ASSERT_FALSE(vertices.empty());
    for (uint32_t v : vertices) s.vertices[v].color = glm::u16vec4(glm::round(glm::clamp(color(s.vertices[v].position), 0.0f, 1.0f) * 65535.0f));
}

// The planar reference (G-buffer + lighting pass from the mirrored eye) and the ray-traced one (the
// material evaluated at the hit) on the same flat mirrors, normal maps off.
struct References {
    app::FloatImage planar, raytraced;
    float exposure = 1.0f;
};
References renderReferences(scene::Scene s, const std::string& camera) {
    GpuFixture f(std::move(s));
    f.headless->settings().apply("normalmap=off");
    References r;
    r.exposure = static_cast<float>(f.headless->settings().number("exposure"));
    r.planar = capture(f, "planar", camera).reflection;
    r.raytraced = capture(f, "raytraced", camera).reflection;
    EXPECT_EQ(f.ctx->validationErrors(), 0u);
    return r;
}

// Both references read the new input the same way. Scored where it changed the planar reflection
// (the pixels that reflect it), the ray-traced reflection must match the planar one: display-space
// PSNR over those pixels, as scoreReflection computes it over all.
void expectReferencesAgree(scene::Scene changed, const char* what) {
    const References base = renderReferences(scene::loadGltf(PPR_DEFAULT_SCENE_FILE), "puddles");
    const References after = renderReferences(std::move(changed), "puddles");
    double squared = 0.0;
    size_t pixels = 0;
    for (size_t i = 0; i < base.planar.rgba.size(); i += 4) {
        const glm::vec3 before(base.planar.rgba[i], base.planar.rgba[i + 1], base.planar.rgba[i + 2]);
        const glm::vec3 planar(after.planar.rgba[i], after.planar.rgba[i + 1], after.planar.rgba[i + 2]);
        const glm::vec3 traced(after.raytraced.rgba[i], after.raytraced.rgba[i + 1], after.raytraced.rgba[i + 2]);
        if (after.planar.rgba[i + 3] != gpu::kReflectionHit || glm::length(planar - before) < 0.01f * glm::length(before) + 1e-4f) continue;
        const glm::vec3 d = gpu::displayFromRadiance(traced, after.exposure) - gpu::displayFromRadiance(planar, after.exposure);
        squared += double(glm::dot(d, d));
        ++pixels;
    }
    const double psnr = pixels == 0 ? 0.0 : squared <= 0.0 ? app::kPsnrCapDb : 10.0 * std::log10(3.0 * double(pixels) / squared);
    std::printf("puddles, %s: %zu reflection pixels changed; there raytraced vs planar PSNR %.2f dB\n", what, pixels, psnr);
    EXPECT_GE(pixels, 50u) << what << ": the puddles should reflect it";
    EXPECT_GE(psnr, 40.0) << what;
}

// The red paint (crates and a sphere, seen in the puddles) glowing orange at 3× the factor's range.
scene::Scene glowingRed() {
    scene::Scene s = scene::loadGltf(PPR_DEFAULT_SCENE_FILE);
    s.materials[size_t(materialNamed(s, "paint_red"))].emissiveFactor = glm::vec3(3.0f, 1.2f, 0.0f);
    return s;
}

TEST(Emissive, BrightensTheSurfaceAndItsReflections) {
    const scene::Scene base = scene::loadGltf(PPR_DEFAULT_SCENE_FILE);
    GpuFixture plain{scene::Scene(base)}, glowing{glowingRed()};
    const app::CaptureResult before = capture(plain, "ppr", "puddles"), after = capture(glowing, "ppr", "puddles");
    double litGain = 0.0, reflectionGain = 0.0;
    for (size_t i = 0; i < before.image.pixels.size(); i += 4) litGain += double(after.image.pixels[i]) - before.image.pixels[i];
    for (size_t i = 0; i < before.reflection.rgba.size(); i += 4) reflectionGain += double(after.reflection.rgba[i]) - before.reflection.rgba[i];
    EXPECT_GT(litGain, 0.0) << "the glowing paint should brighten the frame's red";
    EXPECT_GT(reflectionGain, 0.0) << "PPR should reflect the glow";
    EXPECT_EQ(plain.ctx->validationErrors() + glowing.ctx->validationErrors(), 0u);
}

// The G-buffer writes its emissive target, and the lighting pass reads it, only for a scene with an
// opaque material that emits: the default scene has none (four colour targets), the glowing one five.
// The pictures without it are the old ones bit for bit (the Golden.* captures, recorded before).
TEST(Emissive, TheGBufferHasAnEmissiveTargetOnlyWhereAnOpaqueMaterialEmits) {
    GpuFixture plain{scene::loadGltf(PPR_DEFAULT_SCENE_FILE)}, glowing{glowingRed()};
    EXPECT_FALSE(plain.scene.opaqueMaterialEmits());
    EXPECT_TRUE(glowing.scene.opaqueMaterialEmits());
    for (GpuFixture* f : {&plain, &glowing}) {
        f->headless->setTechnique("planar");  // the reference's mirrored G-buffers too
        const std::string dot = f->headless->capture(f->camera("puddles"), kSize, 1, true).dot;
        const bool emits = f == &glowing;
        EXPECT_NE(dot.find("gbuffer.albedo"), std::string::npos);
        EXPECT_EQ(dot.find("\"gbuffer.emissive") != std::string::npos, emits);
        EXPECT_EQ(dot.find("planar.gbuffer.emissive") != std::string::npos, emits);
        EXPECT_EQ(f->ctx->validationErrors(), 0u);
    }
}

TEST(Emissive, PlanarAndRayTracedReferencesAgreeOnGlowingSurfaces) {
    PPR_SKIP_WITHOUT_RAY_QUERY();
    expectReferencesAgree(glowingRed(), "glowing paint");
}

// Black vertex colours and a black base colour factor draw the same picture, bit for bit, in every
// path; vertex alpha 0 under alpha MASK cuts the surface out as a zero factor alpha does.
TEST(VertexColors, MultiplyTheBaseColourInEveryPath) {
    const scene::Scene base = scene::loadGltf(PPR_DEFAULT_SCENE_FILE);
    const int red = materialNamed(base, "paint_red");
    scene::Scene blackFactor = base, blackVertices = base;
    blackFactor.materials[size_t(red)].baseColorFactor = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
    paintVertices(blackVertices, red, [](glm::vec3) { return glm::vec4(0.0f, 0.0f, 0.0f, 1.0f); });
    EXPECT_FALSE(identical(render(base, "puddles"), render(blackFactor, "puddles")));
    EXPECT_TRUE(identical(render(blackFactor, "puddles"), render(blackVertices, "puddles")));

    scene::Scene cutFactor = base, cutVertices = base;
    for (scene::Scene* s : {&cutFactor, &cutVertices}) {
        s->materials[size_t(red)].masked = true;
        s->materials[size_t(red)].alphaCutoff = 0.5f;
    }
    cutFactor.materials[size_t(red)].baseColorFactor.a = 0.2f;
    paintVertices(cutVertices, red, [](glm::vec3) { return glm::vec4(1.0f, 1.0f, 1.0f, 0.0f); });
    EXPECT_TRUE(identical(render(cutFactor, "overview"), render(cutVertices, "overview")));  // G-buffer and shadow map

    if (!rayQueryMissing().empty()) return;
    EXPECT_TRUE(identical(render(blackFactor, "puddles", "raytraced"), render(blackVertices, "puddles", "raytraced")));
    EXPECT_TRUE(identical(render(cutFactor, "puddles", "raytraced"), render(cutVertices, "puddles", "raytraced")));
}

TEST(VertexColors, PlanarAndRayTracedReferencesAgreeOnAGradient) {
    PPR_SKIP_WITHOUT_RAY_QUERY();
    scene::Scene s = scene::loadGltf(PPR_DEFAULT_SCENE_FILE);
    paintVertices(s, materialNamed(s, "paint_red"), [](glm::vec3 p) { return glm::vec4(glm::fract(p * 0.37f), 1.0f); });
    expectReferencesAgree(std::move(s), "vertex-coloured paint");
}

}  // namespace
}  // namespace ppr::test
