// The checks between reflected layouts and the C++ that creates and binds pipelines (layout_check.hpp):
// pure logic, so every error path is tested without a device.
#include "shader/layout_check.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

using namespace ppr::shader;

namespace {

constexpr VkDescriptorType UBO = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
constexpr VkDescriptorType SSBO = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
constexpr VkDescriptorType CIS = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
constexpr VkDescriptorType SI = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;

template <class F>
std::string logicError(F&& f) {
    try {
        f();
    } catch (const std::logic_error& e) {
        return e.what();
    }
    ADD_FAILURE() << "no std::logic_error";
    return {};
}

ReflectedLayout layout(std::vector<std::pair<uint32_t, VkDescriptorType>> set0) {
    ReflectedLayout r;
    for (auto [binding, type] : set0) {
        ReflectedBinding& b = r.sets[0][binding] = {type, 1, "b"};
        b.name += std::to_string(binding);  // not "b" + ...: GCC 12 warns falsely (-Wrestrict) on that
    }
    return r;
}

TEST(PushSetTypes, ContiguousSetZeroInBindingOrder) {
    EXPECT_EQ(pushSetTypes(layout({{2, SI}, {0, UBO}, {1, CIS}}), 0, 0, "p"), (std::vector<VkDescriptorType>{UBO, CIS, SI}));
    EXPECT_TRUE(pushSetTypes(ReflectedLayout{}, 0, 0, "p").empty());
}

TEST(PushSetTypes, GapNamesPipelineAndBinding) {
    const std::string e = logicError([] { pushSetTypes(layout({{0, UBO}, {2, SI}}), 0, 0, "lighting"); });
    EXPECT_NE(e.find("pipeline 'lighting'"), std::string::npos) << e;
    EXPECT_NE(e.find("binding 2 ('b2') but no binding 1"), std::string::npos) << e;
    EXPECT_NE(logicError([] { pushSetTypes(layout({{1, UBO}}), 0, 0, "p"); }).find("no binding 0"), std::string::npos);
}

TEST(PushSetTypes, ArrayInSetZeroThrows) {
    ReflectedLayout r = layout({{0, UBO}});
    r.sets[0][1] = {CIS, 4, "maps"};
    EXPECT_NE(logicError([&] { pushSetTypes(r, 0, 0, "p"); }).find("binding 1 ('maps') is an array"), std::string::npos);
}

TEST(PushSetTypes, HigherSetsNeedExtraSets) {
    ReflectedLayout r = layout({{0, UBO}});
    r.sets[1][0] = {CIS, 0, "textures"};
    EXPECT_EQ(pushSetTypes(r, 0, 1, "gbuffer").size(), 1u);
    const std::string e = logicError([&] { pushSetTypes(r, 0, 0, "gbuffer"); });
    EXPECT_NE(e.find("pipeline 'gbuffer': the shaders use descriptor set 1"), std::string::npos) << e;
}

TEST(PushSetTypes, PushConstantSizeMustMatch) {
    ReflectedLayout r = layout({{0, UBO}});
    r.pushConstantBytes = 32;
    EXPECT_EQ(pushSetTypes(r, 32, 0, "p").size(), 1u);
    const std::string e = logicError([&] { pushSetTypes(r, 16, 0, "ppr.project"); });
    EXPECT_NE(e.find("pipeline 'ppr.project'"), std::string::npos) << e;
    EXPECT_NE(e.find("32 bytes"), std::string::npos) << e;
    EXPECT_NE(e.find("says 16"), std::string::npos) << e;
    // No block in the shaders: the C++ size stands (a pass may push constants no stage reads).
    EXPECT_EQ(pushSetTypes(layout({{0, UBO}}), 16, 0, "p").size(), 1u);
}

TEST(CheckBindings, MatchingCallsPass) {
    const std::vector<VkDescriptorType> expected{UBO, CIS, SI};
    EXPECT_NO_THROW(checkBindings("lighting", "lighting", expected, expected));
    EXPECT_NO_THROW(checkBindings("empty", "", {}, {}));
}

TEST(CheckBindings, WrongTypeNamesPassPipelineBindingAndTypes) {
    const std::vector<VkDescriptorType> expected{UBO, CIS, SI, SSBO}, given{UBO, CIS, SSBO, SI};
    const std::string e = logicError([&] { checkBindings("planar.resolve", "planar.resolve.3", expected, given); });
    EXPECT_NE(e.find("pass 'planar.resolve.3' (pipeline 'planar.resolve')"), std::string::npos) << e;
    EXPECT_NE(e.find("binding 2: the shader expects STORAGE_IMAGE, given STORAGE_BUFFER"), std::string::npos) << e;
}

TEST(CheckBindings, TooFewAndTooMany) {
    const std::vector<VkDescriptorType> expected{UBO, CIS};
    const std::vector<VkDescriptorType> fewer{UBO}, more{UBO, CIS, SI};
    std::string e = logicError([&] { checkBindings("tonemap", "", expected, fewer); });
    EXPECT_NE(e.find("pipeline 'tonemap'"), std::string::npos) << e;
    EXPECT_NE(e.find("1 bindings given, the shader expects 2; binding 1 (COMBINED_IMAGE_SAMPLER) is missing"), std::string::npos) << e;
    e = logicError([&] { checkBindings("tonemap", "", expected, more); });
    EXPECT_NE(e.find("binding 2 (STORAGE_IMAGE) has no place"), std::string::npos) << e;
}

}  // namespace
