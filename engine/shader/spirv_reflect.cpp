#include "shader/spirv_reflect.hpp"

#include <algorithm>
#include <cstdio>
#include <stdexcept>
#include <unordered_map>
#include <vector>

namespace ppr::shader {
namespace {

// The few SPIR-V enumerants this reads (SPIR-V spec, section 3).
constexpr uint32_t kMagic = 0x07230203u;
enum Op : uint32_t {
    OpName = 5,
    OpTypeBool = 20,
    OpTypeInt = 21,
    OpTypeFloat = 22,
    OpTypeVector = 23,
    OpTypeMatrix = 24,
    OpTypeImage = 25,
    OpTypeSampler = 26,
    OpTypeSampledImage = 27,
    OpTypeArray = 28,
    OpTypeRuntimeArray = 29,
    OpTypeStruct = 30,
    OpTypePointer = 32,
    OpConstant = 43,
    OpSpecConstant = 50,
    OpVariable = 59,
    OpDecorate = 71,
    OpMemberDecorate = 72,
    OpTypeAccelerationStructureKHR = 5341,
};
enum Decoration : uint32_t { Block = 2, BufferBlock = 3, RowMajor = 4, ArrayStride = 6, MatrixStride = 7, Binding = 33, DescriptorSet = 34, Offset = 35 };
enum StorageClass : uint32_t { UniformConstant = 0, Uniform = 2, PushConstant = 9, StorageBuffer = 12 };
enum Dim : uint32_t { DimBuffer = 5, DimSubpassData = 6 };
constexpr int kMaxTypeDepth = 32;  // deeper nesting means a malformed (cyclic) type graph

struct Decorations {
    std::optional<uint32_t> set, binding, arrayStride;
    bool block = false, bufferBlock = false;
};
struct MemberDecorations {
    std::optional<uint32_t> offset;
    uint32_t matrixStride = 0;
    bool rowMajor = false;
};
struct Type {
    uint32_t op = 0;
    std::vector<uint32_t> operands;  // the words after the result id
};
struct Variable {
    uint32_t id, pointerType, storage;
};

class Module {
public:
    Module(std::span<const uint32_t> words, const std::string& what) : what_(what) { parse(words); }

    ReflectedLayout layout() const {
        ReflectedLayout out;
        for (const Variable& v : variables_) {
            if (v.storage == PushConstant) {
                const uint32_t bytes = sizeOf(pointee(v), nullptr, 0);
                out.pushConstantBytes = std::max(out.pushConstantBytes.value_or(0), bytes);
                continue;
            }
            if (v.storage != UniformConstant && v.storage != Uniform && v.storage != StorageBuffer) continue;
            const Decorations d = decorationsOf(v.id);
            if (!d.binding) fail("resource '" + nameOf(v.id) + "' has no Binding decoration");
            ReflectedLayout one;
            one.sets[d.set.value_or(0)][*d.binding] = describe(v);
            mergeStage(out, one, what_);  // two variables aliasing one binding must agree too
        }
        return out;
    }

private:
    [[noreturn]] void fail(const std::string& why) const { throw std::runtime_error("SPIR-V reflection of " + what_ + ": " + why); }

    void parse(std::span<const uint32_t> words) {
        if (words.size() < 5) fail("only " + std::to_string(words.size()) + " words, shorter than the SPIR-V header");
        if (words[0] != kMagic) {
            char hex[16];
            std::snprintf(hex, sizeof hex, "0x%08x", words[0]);
            fail(std::string("not SPIR-V: magic number ") + hex + " (expected 0x07230203)");
        }
        for (size_t at = 5; at < words.size();) {
            const uint32_t count = words[at] >> 16, op = words[at] & 0xFFFFu;
            if (count == 0) fail("instruction at word " + std::to_string(at) + " has length 0");
            if (count > words.size() - at) fail("truncated: instruction at word " + std::to_string(at) + " runs past the end");
            instruction(op, words.subspan(at + 1, count - 1), at);
            at += count;
        }
    }

    void instruction(uint32_t op, std::span<const uint32_t> in, size_t at) {
        auto word = [&](size_t k) {
            if (k >= in.size()) fail("opcode " + std::to_string(op) + " at word " + std::to_string(at) + " is too short");
            return in[k];
        };
        switch (op) {
            case OpName: {
                const uint32_t id = word(0);  // before subspan(1): the operands may be empty
                names_[id] = literalString(in.subspan(1));
                break;
            }
            case OpDecorate: {
                Decorations& d = decorations_[word(0)];
                switch (word(1)) {
                    case Block: d.block = true; break;
                    case BufferBlock: d.bufferBlock = true; break;
                    case ArrayStride: d.arrayStride = word(2); break;
                    case Binding: d.binding = word(2); break;
                    case DescriptorSet: d.set = word(2); break;
                    default: break;
                }
                break;
            }
            case OpMemberDecorate: {
                const uint32_t member = word(1);
                if (member > 0xFFFFu) fail("member index " + std::to_string(member) + " out of range");
                std::vector<MemberDecorations>& all = members_[word(0)];
                if (all.size() <= member) all.resize(member + 1);
                switch (word(2)) {
                    case Offset: all[member].offset = word(3); break;
                    case MatrixStride: all[member].matrixStride = word(3); break;
                    case RowMajor: all[member].rowMajor = true; break;
                    default: break;
                }
                break;
            }
            case OpTypeBool: case OpTypeInt: case OpTypeFloat: case OpTypeVector: case OpTypeMatrix: case OpTypeImage:
            case OpTypeSampler: case OpTypeSampledImage: case OpTypeArray: case OpTypeRuntimeArray: case OpTypeStruct:
            case OpTypePointer: case OpTypeAccelerationStructureKHR: {
                const uint32_t id = word(0);  // before in.begin() + 1: the operands may be empty
                types_[id] = Type{op, std::vector<uint32_t>(in.begin() + 1, in.end())};
                break;
            }
            case OpConstant: case OpSpecConstant: constants_[word(1)] = word(2); break;
            case OpVariable: variables_.push_back({word(1), word(0), word(2)}); break;
            default: break;
        }
    }

    // A nul-terminated UTF-8 literal packed four bytes a word, little end first; stops at the operands' end.
    static std::string literalString(std::span<const uint32_t> words) {
        std::string s;
        for (uint32_t w : words)
            for (int b = 0; b < 4; ++b) {
                const char c = static_cast<char>((w >> (8 * b)) & 0xFFu);
                if (c == '\0') return s;
                s += c;
            }
        return s;
    }

    const Type& type(uint32_t id) const {
        auto it = types_.find(id);
        if (it == types_.end()) fail("type %" + std::to_string(id) + " is used but not declared");
        return it->second;
    }
    uint32_t operand(const Type& t, size_t k) const {
        if (k >= t.operands.size()) fail("type instruction (opcode " + std::to_string(t.op) + ") is too short");
        return t.operands[k];
    }
    uint32_t constant(uint32_t id) const {
        auto it = constants_.find(id);
        if (it == constants_.end()) fail("array length %" + std::to_string(id) + " is not a constant");
        return it->second;
    }
    Decorations decorationsOf(uint32_t id) const {
        auto it = decorations_.find(id);
        return it == decorations_.end() ? Decorations{} : it->second;
    }
    std::string nameOf(uint32_t id) const {
        auto it = names_.find(id);
        if (it != names_.end() && !it->second.empty()) return it->second;
        std::string anonymous = "%";  // appended, not "%" + ...: GCC 12 warns falsely (-Wrestrict) on that
        return anonymous += std::to_string(id);
    }
    uint32_t pointee(const Variable& v) const {
        const Type& p = type(v.pointerType);
        if (p.op != OpTypePointer) fail("variable '" + nameOf(v.id) + "' does not have a pointer type");
        return operand(p, 1);
    }

    ReflectedBinding describe(const Variable& v) const {
        ReflectedBinding b;
        uint32_t id = pointee(v);
        for (int depth = 0;; ++depth) {  // descriptor arrays: multiply out the dimensions
            if (depth > kMaxTypeDepth) fail("type of '" + nameOf(v.id) + "' nests too deeply");
            const Type& t = type(id);
            if (t.op == OpTypeArray) b.count *= constant(operand(t, 1));
            else if (t.op == OpTypeRuntimeArray) b.count = 0;
            else break;
            id = operand(t, 0);
        }
        const Type& t = type(id);
        const Decorations d = decorationsOf(id);
        b.name = names_.count(v.id) && !names_.at(v.id).empty() ? names_.at(v.id) : nameOf(id);  // blocks: the type name
        switch (t.op) {
            case OpTypeStruct:
                if (v.storage == StorageBuffer || d.bufferBlock) b.type = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
                else if (v.storage == Uniform && d.block) b.type = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
                else fail("block '" + b.name + "' is neither a uniform nor a storage buffer");
                break;
            case OpTypeImage: b.type = imageType(t, b.name, false); break;
            case OpTypeSampledImage: b.type = imageType(type(operand(t, 0)), b.name, true); break;
            case OpTypeSampler: b.type = VK_DESCRIPTOR_TYPE_SAMPLER; break;
            case OpTypeAccelerationStructureKHR: b.type = VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR; break;
            default: fail("resource '" + b.name + "' has an unsupported type (opcode " + std::to_string(t.op) + ")");
        }
        return b;
    }

    // OpTypeImage operands: sampled type, Dim, depth, arrayed, MS, sampled (1: with a sampler, 2: storage), format.
    VkDescriptorType imageType(const Type& t, const std::string& name, bool withSampler) const {
        if (t.op != OpTypeImage) fail("sampled image '" + name + "' does not wrap an image type");
        const uint32_t dim = operand(t, 1), sampled = operand(t, 5);
        if (dim == DimSubpassData) return VK_DESCRIPTOR_TYPE_INPUT_ATTACHMENT;
        if (dim == DimBuffer) {
            if (sampled == 1) return VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER;
            if (sampled == 2) return VK_DESCRIPTOR_TYPE_STORAGE_TEXEL_BUFFER;
        } else {
            if (sampled == 1) return withSampler ? VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER : VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE;
            if (sampled == 2 && !withSampler) return VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
        }
        fail("image '" + name + "' has Sampled=" + std::to_string(sampled) + ", which is no Vulkan descriptor");
    }

    // Bytes from the start of `id` to the end of its last member, as laid out by the Offset,
    // ArrayStride and MatrixStride decorations (`m`: those of the struct member being sized).
    uint32_t sizeOf(uint32_t id, const MemberDecorations* m, int depth) const {
        if (depth > kMaxTypeDepth) fail("push-constant type nests too deeply");
        const Type& t = type(id);
        switch (t.op) {
            case OpTypeInt: case OpTypeFloat: return operand(t, 0) / 8;
            case OpTypeVector: return operand(t, 1) * sizeOf(operand(t, 0), m, depth + 1);
            case OpTypeMatrix: {
                const uint32_t columns = operand(t, 1);
                const Type& column = type(operand(t, 0));
                if (column.op != OpTypeVector) fail("matrix column is not a vector");
                if (!m || m->matrixStride == 0) return columns * sizeOf(operand(t, 0), m, depth + 1);
                return (m->rowMajor ? operand(column, 1) : columns) * m->matrixStride;
            }
            case OpTypeArray: {
                const uint32_t length = constant(operand(t, 1));
                const std::optional<uint32_t> stride = decorationsOf(id).arrayStride;
                return length * (stride ? *stride : sizeOf(operand(t, 0), m, depth + 1));
            }
            case OpTypeStruct: {
                if (auto known = structSizes_.find(id); known != structSizes_.end()) return known->second;  // shared types: size once
                auto it = members_.find(id);
                uint32_t end = 0;
                for (size_t k = 0; k < t.operands.size(); ++k) {
                    const MemberDecorations* md = it != members_.end() && k < it->second.size() ? &it->second[k] : nullptr;
                    if (!md || !md->offset) fail("member " + std::to_string(k) + " of '" + nameOf(id) + "' has no Offset");
                    end = std::max(end, *md->offset + sizeOf(t.operands[k], md, depth + 1));
                }
                return structSizes_[id] = end;
            }
            default: fail("push constant '" + nameOf(id) + "' has a type (opcode " + std::to_string(t.op) + ") this reader cannot size");
        }
    }

    std::string what_;
    std::unordered_map<uint32_t, Type> types_;
    std::unordered_map<uint32_t, uint32_t> constants_;
    std::unordered_map<uint32_t, std::string> names_;
    std::unordered_map<uint32_t, Decorations> decorations_;
    std::unordered_map<uint32_t, std::vector<MemberDecorations>> members_;
    std::vector<Variable> variables_;
    mutable std::unordered_map<uint32_t, uint32_t> structSizes_;
};

}  // namespace

ReflectedLayout reflectSpirv(std::span<const uint32_t> words, const std::string& what) { return Module(words, what).layout(); }

void mergeStage(ReflectedLayout& into, const ReflectedLayout& stage, const std::string& what) {
    for (const auto& [set, bindings] : stage.sets)
        for (const auto& [binding, b] : bindings) {
            auto [it, added] = into.sets[set].try_emplace(binding, b);
            const ReflectedBinding& have = it->second;
            if (added || (have.type == b.type && have.count == b.count)) continue;
            auto describe = [](const ReflectedBinding& r) {
                return std::string(descriptorTypeName(r.type)) + "[" + std::to_string(r.count) + "] '" + r.name + "'";
            };
            throw std::runtime_error(what + ": set " + std::to_string(set) + " binding " + std::to_string(binding) + " is " +
                                     describe(have) + " in one declaration and " + describe(b) + " in another");
        }
    if (stage.pushConstantBytes)
        into.pushConstantBytes = std::max(into.pushConstantBytes.value_or(0), *stage.pushConstantBytes);
}

const char* descriptorTypeName(VkDescriptorType type) {
    switch (type) {
        case VK_DESCRIPTOR_TYPE_SAMPLER: return "SAMPLER";
        case VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER: return "COMBINED_IMAGE_SAMPLER";
        case VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE: return "SAMPLED_IMAGE";
        case VK_DESCRIPTOR_TYPE_STORAGE_IMAGE: return "STORAGE_IMAGE";
        case VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER: return "UNIFORM_TEXEL_BUFFER";
        case VK_DESCRIPTOR_TYPE_STORAGE_TEXEL_BUFFER: return "STORAGE_TEXEL_BUFFER";
        case VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER: return "UNIFORM_BUFFER";
        case VK_DESCRIPTOR_TYPE_STORAGE_BUFFER: return "STORAGE_BUFFER";
        case VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC: return "UNIFORM_BUFFER_DYNAMIC";
        case VK_DESCRIPTOR_TYPE_STORAGE_BUFFER_DYNAMIC: return "STORAGE_BUFFER_DYNAMIC";
        case VK_DESCRIPTOR_TYPE_INPUT_ATTACHMENT: return "INPUT_ATTACHMENT";
        case VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR: return "ACCELERATION_STRUCTURE_KHR";
        default: return "UNKNOWN_DESCRIPTOR_TYPE";
    }
}

}  // namespace ppr::shader
