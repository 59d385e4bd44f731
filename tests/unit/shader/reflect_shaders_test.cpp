// Reflection of the project's real shaders (the SPIR-V the build embeds, cmake/Shaders.cmake): the
// layouts the passes used to spell out by hand, now read from the GLSL.
#include "shader/spirv_reflect.hpp"

#include "gpu/scene_data.h"
#include "ppr_project/ppr_project.h"

#include "gbuffer_frag.h"
#include "gbuffer_vert.h"
#include "lighting_comp.h"
#include "lighting_no_emissive_comp.h"
#include "ppr_project_comp.h"
#include "shadow_vert.h"
#include "tonemap_frag.h"
#include "fullscreen_vert.h"

#include <gtest/gtest.h>

#include <random>
#include <stdexcept>
#include <vector>

using namespace ppr::shader;

namespace {

constexpr VkDescriptorType UBO = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
constexpr VkDescriptorType SSBO = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
constexpr VkDescriptorType CIS = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
constexpr VkDescriptorType SI = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;

template <size_t N>
std::span<const uint32_t> words(const uint32_t (&spirv)[N]) {
    return {spirv, N};
}

std::vector<VkDescriptorType> typesOf(const ReflectedLayout& r, uint32_t set) {
    std::vector<VkDescriptorType> out;
    for (const auto& [binding, b] : r.sets.at(set)) {
        EXPECT_EQ(binding, out.size()) << "bindings of set " << set << " are not contiguous";
        EXPECT_EQ(b.count, 1u) << "binding " << binding;
        out.push_back(b.type);
    }
    return out;
}

TEST(ReflectShaders, PprProjectHasFourteenBindingsInOrder) {
    const ReflectedLayout r = reflectSpirv(words(ppr_project_comp), "ppr_project.comp");
    ASSERT_EQ(r.sets.size(), 1u);
    EXPECT_EQ(typesOf(r, 0), (std::vector<VkDescriptorType>{UBO, CIS, SSBO, SSBO, SI, SSBO, SSBO, SSBO, SSBO, SI, SSBO, CIS, SSBO, SSBO}));
    EXPECT_EQ(r.sets.at(0).at(1).name, "depthTex");
    EXPECT_EQ(r.sets.at(0).at(11).name, "normalTex");  // --set facing
    EXPECT_EQ(r.sets.at(0).at(12).name, "ReachTiles");  // the reach pass's list (indirect dispatch)
    EXPECT_EQ(r.sets.at(0).at(13).name, "Visible");     // the bounds pass's compacted reflectors
    EXPECT_EQ(r.sets.at(0).at(4).name, "intermediate");
    ASSERT_TRUE(r.pushConstantBytes.has_value());
    EXPECT_EQ(*r.pushConstantBytes, sizeof(ppr::gpu::PprProjectPush));
}

TEST(ReflectShaders, LightingSamplersAndStorageImage) {
    // sampler2DShadow is a combined image sampler too; the output is a storage image (before the
    // emissive target, added later); no push block.
    const ReflectedLayout r = reflectSpirv(words(lighting_comp), "lighting.comp");
    EXPECT_EQ(typesOf(r, 0), (std::vector<VkDescriptorType>{UBO, CIS, CIS, CIS, CIS, CIS, SI, CIS}));  // then gbuffer.emissive
    EXPECT_EQ(r.sets.at(0).at(0).type, UBO);
    EXPECT_FALSE(r.pushConstantBytes.has_value());
    // The variant for a G-buffer without the emissive target: the same bindings but that one.
    const ReflectedLayout plain = reflectSpirv(words(lighting_no_emissive_comp), "lighting_no_emissive.comp");
    EXPECT_EQ(typesOf(plain, 0), (std::vector<VkDescriptorType>{UBO, CIS, CIS, CIS, CIS, CIS, SI}));
}

TEST(ReflectShaders, GBufferStagesMergeWithBindlessSet) {
    const ReflectedLayout vert = reflectSpirv(words(gbuffer_vert), "gbuffer.vert");
    EXPECT_EQ(typesOf(vert, 0), (std::vector<VkDescriptorType>{UBO, SSBO}));
    ReflectedLayout merged = vert;
    mergeStage(merged, reflectSpirv(words(gbuffer_frag), "gbuffer.frag"), "gbuffer");
    EXPECT_EQ(typesOf(merged, 0), (std::vector<VkDescriptorType>{UBO, SSBO, SSBO, SSBO, SSBO, SSBO}));
    // Set 1: the scene's bindless textures, a runtime-sized array of combined image samplers.
    ASSERT_EQ(merged.sets.count(1), 1u);
    ASSERT_EQ(merged.sets.at(1).size(), 1u);
    EXPECT_EQ(merged.sets.at(1).at(0).type, CIS);
    EXPECT_EQ(merged.sets.at(1).at(0).count, 0u);
    EXPECT_EQ(merged.sets.at(1).at(0).name, "textures");
    ASSERT_TRUE(merged.pushConstantBytes.has_value());
    EXPECT_EQ(*merged.pushConstantBytes, sizeof(ppr::gpu::DrawPush));
}

TEST(ReflectShaders, VertexStageWithoutResourcesMerges) {
    ReflectedLayout r = reflectSpirv(words(fullscreen_vert), "fullscreen.vert");
    EXPECT_TRUE(r.sets.empty());
    mergeStage(r, reflectSpirv(words(tonemap_frag), "tonemap.frag"), "tonemap");
    EXPECT_EQ(typesOf(r, 0), (std::vector<VkDescriptorType>{UBO, CIS}));
}

TEST(ReflectShaders, ShadowVertexOnly) {
    const ReflectedLayout r = reflectSpirv(words(shadow_vert), "shadow.vert");
    EXPECT_EQ(typesOf(r, 0), (std::vector<VkDescriptorType>{UBO, SSBO}));
    EXPECT_EQ(r.pushConstantBytes.value_or(0), sizeof(ppr::gpu::DrawPush));
}

// Cut or corrupted real SPIR-V must give a result or a runtime_error, never a crash or another exception.
TEST(ReflectShaders, DamagedSpirvNeverCrashes) {
    const std::span<const uint32_t> good = words(ppr_project_comp);
    for (size_t n = 0; n < good.size(); ++n) {
        try {
            reflectSpirv(good.first(n), "cut");
        } catch (const std::runtime_error&) {
        }
    }
    std::mt19937 rng(7);
    std::vector<uint32_t> damaged;
    for (int round = 0; round < 3000; ++round) {
        damaged.assign(good.begin(), good.end());
        for (int k = 0; k < 1 + round % 4; ++k) {
            const size_t at = 5 + rng() % (damaged.size() - 5);
            damaged[at] = round % 2 ? rng() : damaged[at] ^ (1u << (rng() % 32));
        }
        try {
            reflectSpirv(damaged, "damaged");
        } catch (const std::runtime_error&) {
        }
    }
}

}  // namespace
