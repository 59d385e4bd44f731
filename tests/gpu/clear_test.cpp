// `--set clear=transfer|compute`: the two ways passes clear images leave the same bits in every
// technique (TAA's distance image and the glass atlas included), and each builds the pass kind it
// names. Validation + synchronization validation on throughout.
#include "common/clear_pass.hpp"
#include "gpu_test_util.hpp"
#include "techniques/technique_table.hpp"

#include <cstring>

namespace ppr::test {
namespace {

constexpr VkExtent2D kSize{320, 180};

app::CaptureResult render(GpuFixture& f, const std::string& technique, const std::string& camera, const std::string& clear,
                          const std::string& taa) {
    f.headless->setTechnique(technique);
    f.headless->settings().set("clear", clear);
    f.headless->settings().set("taa", taa);
    return f.headless->capture(f.camera(camera), kSize, taa == "1" ? 3 : 1, true, true);
}

size_t transferWrites(const std::string& dot) {
    size_t n = 0;
    for (size_t at = dot.find("\"transferDst\""); at != std::string::npos; at = dot.find("\"transferDst\"", at + 1)) ++n;
    return n;
}

// (memcmp's pointers must not be null even for 0 bytes: an image a technique does not make is empty.)
bool sameBytes(const void* a, size_t aBytes, const void* b, size_t bBytes) {
    return aBytes == bBytes && (aBytes == 0 || std::memcmp(a, b, aBytes) == 0);
}

TEST(ImageClear, ComputeAndTransferClearsGiveIdenticalFrames) {
    GpuFixture f;
    for (const std::string& technique : app::techniqueNames()) {
        if (f.renderer->unsupported(technique, kSize) != "") continue;  // raytraced without ray queries
        for (const char* camera : {"overview", "puddles"})
            for (const char* taa : {"0", "1"}) {
                const app::CaptureResult transfer = render(f, technique, camera, "transfer", taa);
                const app::CaptureResult compute = render(f, technique, camera, "compute", taa);
                const std::string where = technique + " on " + camera + " taa=" + taa;
                EXPECT_TRUE(sameBytes(transfer.image.pixels.data(), transfer.image.pixels.size(), compute.image.pixels.data(),
                                      compute.image.pixels.size()))
                    << where << ": the frame differs";
                EXPECT_TRUE(sameBytes(transfer.reflection.rgba.data(), transfer.reflection.rgba.size() * sizeof(float),
                                      compute.reflection.rgba.data(), compute.reflection.rgba.size() * sizeof(float)))
                    << where << ": the reflection differs";
                EXPECT_TRUE(sameBytes(transfer.glassReflection.rgba.data(), transfer.glassReflection.rgba.size() * sizeof(float),
                                      compute.glassReflection.rgba.data(), compute.glassReflection.rgba.size() * sizeof(float)))
                    << where << ": the glass atlas differs";
                // The setting reaches the passes: PPR's clears are no longer transfer writes.
                if (technique == "ppr") EXPECT_LT(transferWrites(compute.dot), transferWrites(transfer.dot)) << where;
            }
    }
    EXPECT_EQ(f.ctx->validationErrors(), 0u);
}

// addClearPass builds the pass kind FrameInputs asks for, on float and integer images alike.
TEST(ImageClear, BuildsAComputePassOnlyWhenAsked) {
    GpuFixture f;
    const passes::ImageClear clear(*f.ctx);
    for (const bool compute : {false, true})
        for (const VkFormat format : {VK_FORMAT_R16G16B16A16_SFLOAT, VK_FORMAT_R32_UINT}) {
            graph::RenderGraph g;
            passes::FrameInputs in;
            in.clear = &clear;
            in.computeClear = compute;
            passes::addClearPass(g, in, "test.clear", g.createImage("test", {64, 32, format, 1}), VkClearColorValue{});
            g.compile();
            ASSERT_EQ(g.compiledPasses().size(), 1u);
            EXPECT_EQ(g.compiledPasses()[0].kind, compute ? graph::QueueKind::Compute : graph::QueueKind::Transfer)
                << "format " << format << " compute=" << compute;
        }
    EXPECT_TRUE(passes::ImageClear::computeIsCheaper({.type = "discrete"}));
    EXPECT_FALSE(passes::ImageClear::computeIsCheaper({.type = "cpu"}));
}

}  // namespace
}  // namespace ppr::test
