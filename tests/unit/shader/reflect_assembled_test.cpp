// Reflection of hand-assembled SPIR-V (spirv_asm.hpp): descriptor kinds this project's shaders do not
// (yet) use, push-constant sizing, stage merging, and malformed input giving a clear exception.
#include "shader/spirv_reflect.hpp"

#include "spirv_asm.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

using namespace ppr::shader;
using namespace ppr::test;

namespace {

// Runs `f`, expecting std::runtime_error whose message contains `part`.
template <class F>
void expectError(F&& f, const std::string& part) {
    try {
        f();
        ADD_FAILURE() << "no exception; expected one mentioning \"" << part << "\"";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
    }
}

TEST(ReflectAssembled, DescriptorKinds) {
    SpirvAsm a;
    a.resource(a.image(kDim2D, 2), 0, 0);
    a.resource(a.sampler(), 0, 1);
    a.resource(a.accelerationStructure(), 0, 2);
    a.resource(a.sampledImage(a.image(kDimBuffer, 1)), 0, 3);
    a.resource(a.image(kDimBuffer, 2), 0, 4);
    a.resource(a.image(kDim2D, 1), 0, 5);
    a.resource(a.sampledImage(a.image(kDim2D, 1)), 0, 6);
    a.resource(a.image(kDimSubpassData, 2), 0, 7);
    const ReflectedLayout r = reflectSpirv(a.words(), "kinds");
    const auto& set0 = r.sets.at(0);
    ASSERT_EQ(set0.size(), 8u);
    EXPECT_EQ(set0.at(0).type, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE);
    EXPECT_EQ(set0.at(1).type, VK_DESCRIPTOR_TYPE_SAMPLER);
    EXPECT_EQ(set0.at(2).type, VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR);
    EXPECT_EQ(set0.at(3).type, VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER);
    EXPECT_EQ(set0.at(4).type, VK_DESCRIPTOR_TYPE_STORAGE_TEXEL_BUFFER);
    EXPECT_EQ(set0.at(5).type, VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE);
    EXPECT_EQ(set0.at(6).type, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER);
    EXPECT_EQ(set0.at(7).type, VK_DESCRIPTOR_TYPE_INPUT_ATTACHMENT);
    EXPECT_FALSE(r.pushConstantBytes.has_value());
}

TEST(ReflectAssembled, BlocksAndDescriptorArrays) {
    SpirvAsm a;
    const uint32_t f = a.typeFloat();
    a.resource(a.array(a.structOf({f}, {0}, kBlock), 4), 2, 0, kUniform);   // uniform Ubo { } ubos[4]
    a.resource(a.structOf({f}, {0}, kBufferBlock), 0, 0, kUniform);          // pre-1.3 style storage buffer
    a.resource(a.structOf({a.runtimeArray(f)}, {0}, kBlock), 0, 1, kStorageBuffer);
    a.resource(a.runtimeArray(a.sampledImage(a.image(kDim2D, 1))), 1, 0);     // bindless textures[]
    a.resource(a.array(a.array(a.image(kDim2D, 2), 3), 2), 1, 1);             // image2D grid[2][3]
    const ReflectedLayout r = reflectSpirv(a.words(), "blocks");
    EXPECT_EQ(r.sets.at(2).at(0).type, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER);
    EXPECT_EQ(r.sets.at(2).at(0).count, 4u);
    EXPECT_EQ(r.sets.at(0).at(0).type, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER);
    EXPECT_EQ(r.sets.at(0).at(1).type, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER);
    EXPECT_EQ(r.sets.at(1).at(0).type, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER);
    EXPECT_EQ(r.sets.at(1).at(0).count, 0u);
    EXPECT_EQ(r.sets.at(1).at(1).type, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE);
    EXPECT_EQ(r.sets.at(1).at(1).count, 6u);
}

TEST(ReflectAssembled, PushConstantSizeIsFurthestMemberEnd) {
    SpirvAsm a;
    const uint32_t f = a.typeFloat(), u = a.typeUint();
    const uint32_t v4 = a.vector(f, 4), m4 = a.matrix(v4, 4);
    const uint32_t inner = a.structOf({u, u, u}, {0, 4, 8}, kNoBlock);
    // Declared out of offset order: the size is the furthest end, not the last member's.
    const uint32_t push = a.structOf({u, v4, m4, a.array(f, 3, 4), inner}, {108, 0, 16, 80, 92}, kBlock);
    a.op(72, {push, 2, 7, 16});  // MatrixStride 16 on the mat4 member
    a.variable(push, kPushConstant, std::nullopt);
    const ReflectedLayout r = reflectSpirv(a.words(), "push");
    EXPECT_TRUE(r.sets.empty());
    ASSERT_TRUE(r.pushConstantBytes.has_value());
    EXPECT_EQ(*r.pushConstantBytes, 112u);
}

TEST(ReflectAssembled, PushConstantMatrixStride) {
    SpirvAsm a;
    const uint32_t f = a.typeFloat();
    const uint32_t m = a.matrix(a.vector(f, 3), 4);  // mat4x3: 4 columns of vec3
    const uint32_t push = a.structOf({m}, {0}, kBlock);
    a.op(72, {push, 0, 7, 16});
    a.variable(push, kPushConstant, std::nullopt);
    EXPECT_EQ(reflectSpirv(a.words(), "colmajor").pushConstantBytes.value_or(0), 64u);
    a.op(72, {push, 0, 4});  // RowMajor: 3 rows of stride 16
    EXPECT_EQ(reflectSpirv(a.words(), "rowmajor").pushConstantBytes.value_or(0), 48u);
}

TEST(ReflectAssembled, StagesMerge) {
    SpirvAsm vs, fs;
    vs.resource(vs.structOf({vs.typeFloat()}, {0}, kBlock), 0, 0, kUniform);
    vs.variable(vs.structOf({vs.typeUint()}, {0}, kBlock), kPushConstant, std::nullopt);
    fs.resource(fs.structOf({fs.typeFloat()}, {0}, kBlock), 0, 0, kUniform);
    fs.resource(fs.sampledImage(fs.image(kDim2D, 1)), 0, 1);
    fs.variable(fs.structOf({fs.typeUint(), fs.typeUint()}, {0, 4}, kBlock), kPushConstant, std::nullopt);
    ReflectedLayout r = reflectSpirv(vs.words(), "merge.vert");
    mergeStage(r, reflectSpirv(fs.words(), "merge.frag"), "merge");
    ASSERT_EQ(r.sets.at(0).size(), 2u);
    EXPECT_EQ(r.sets.at(0).at(0).type, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER);
    EXPECT_EQ(r.sets.at(0).at(1).type, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER);
    EXPECT_EQ(r.pushConstantBytes.value_or(0), 8u);
}

TEST(ReflectAssembled, StagesDisagreeingOnABindingThrow) {
    SpirvAsm vs, fs;
    vs.resource(vs.structOf({vs.typeFloat()}, {0}, kBlock), 0, 3, kStorageBuffer);
    fs.resource(fs.image(kDim2D, 2), 0, 3);
    ReflectedLayout r = reflectSpirv(vs.words(), "x.vert");
    const ReflectedLayout frag = reflectSpirv(fs.words(), "x.frag");
    expectError([&] { mergeStage(r, frag, "pipeline 'x'"); }, "pipeline 'x': set 0 binding 3 is STORAGE_BUFFER");
    expectError([&] { mergeStage(r, frag, "pipeline 'x'"); }, "STORAGE_IMAGE");
}

TEST(ReflectAssembled, AliasedBindingInOneStageMustAgree) {
    SpirvAsm a;
    a.resource(a.image(kDim2D, 2), 0, 0);
    a.resource(a.sampledImage(a.image(kDim2D, 1)), 0, 0);
    expectError([&] { reflectSpirv(a.words(), "alias.comp"); }, "alias.comp: set 0 binding 0");
}

TEST(ReflectAssembled, WrongMagic) {
    SpirvAsm a;
    std::vector<uint32_t> w = a.words();
    w[0] = 0x03022307u;  // byte-swapped
    expectError([&] { reflectSpirv(w, "swapped.comp"); }, "swapped.comp: not SPIR-V: magic number 0x03022307");
    const std::vector<uint32_t> text{0x65726f63u, 0x20202020u, 0u, 0u, 0u, 0u};
    expectError([&] { reflectSpirv(text, "text"); }, "not SPIR-V");
}

TEST(ReflectAssembled, TooShortForHeader) {
    expectError([] { reflectSpirv({}, "empty"); }, "shorter than the SPIR-V header");
    const std::vector<uint32_t> w{0x07230203u, 0x00010600u};
    expectError([&] { reflectSpirv(w, "two"); }, "shorter than the SPIR-V header");
}

TEST(ReflectAssembled, TruncatedInstruction) {
    SpirvAsm a;
    a.resource(a.image(kDim2D, 2), 0, 0);
    std::vector<uint32_t> w = a.words();
    w.pop_back();  // the last OpDecorate loses its literal
    expectError([&] { reflectSpirv(w, "cut"); }, "truncated");
}

TEST(ReflectAssembled, ZeroLengthInstruction) {
    SpirvAsm a;
    std::vector<uint32_t> w = a.words();
    w.push_back(0u);
    expectError([&] { reflectSpirv(w, "zero"); }, "length 0");
}

TEST(ReflectAssembled, InstructionShorterThanItsOperands) {
    SpirvAsm a;
    a.op(71, {5});  // OpDecorate without a decoration
    expectError([&] { reflectSpirv(a.words(), "short"); }, "too short");
    SpirvAsm b;
    b.op(5, {});  // OpName without a target
    expectError([&] { reflectSpirv(b.words(), "name"); }, "too short");
    SpirvAsm c;
    const uint32_t image = c.result(25, {c.typeFloat()});  // OpTypeImage missing Dim and the rest
    c.resource(image, 0, 0);
    expectError([&] { reflectSpirv(c.words(), "image"); }, "too short");
}

TEST(ReflectAssembled, MissingBindingDecoration) {
    SpirvAsm a;
    a.variable(a.image(kDim2D, 2), kUniformConstant, 0, std::nullopt);
    expectError([&] { reflectSpirv(a.words(), "nobinding"); }, "no Binding decoration");
}

TEST(ReflectAssembled, UndeclaredAndCyclicTypes) {
    SpirvAsm a;
    a.variable(999, kUniformConstant, 0, 0);  // pointer to a type that does not exist
    expectError([&] { reflectSpirv(a.words(), "undeclared"); }, "not declared");

    SpirvAsm b;
    const uint32_t len = b.constant(2), self = b.id();
    b.op(28, {self, self, len});  // an array of itself
    b.resource(self, 0, 0);
    expectError([&] { reflectSpirv(b.words(), "cyclic"); }, "nests too deeply");

    SpirvAsm c;
    const uint32_t s = c.id();
    c.op(30, {s, s});  // a push-constant struct that contains itself
    c.op(72, {s, 0, 35, 0});
    c.variable(s, kPushConstant, std::nullopt);
    expectError([&] { reflectSpirv(c.words(), "cyclic push"); }, "nests too deeply");
}

TEST(ReflectAssembled, UnsupportedResources) {
    SpirvAsm a;
    a.resource(a.image(kDim2D, 0), 0, 0);  // Sampled=0: only known at run time, no Vulkan descriptor
    expectError([&] { reflectSpirv(a.words(), "sampled0"); }, "Sampled=0");
    SpirvAsm b;
    b.resource(b.structOf({b.typeFloat()}, {0}, kNoBlock), 0, 0, kUniform);
    expectError([&] { reflectSpirv(b.words(), "noblock"); }, "neither a uniform nor a storage buffer");
    SpirvAsm c;
    const uint32_t f = c.typeFloat(), arr = c.id();
    c.op(28, {arr, f, f});  // array length is a type, not a constant
    c.resource(arr, 0, 0);
    expectError([&] { reflectSpirv(c.words(), "len"); }, "not a constant");
}

}  // namespace
