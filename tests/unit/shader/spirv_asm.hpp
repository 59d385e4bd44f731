#pragma once
// A tiny SPIR-V assembler for the reflection tests: just the instructions spirv_reflect.cpp reads,
// with ids handed out in order. Enough to build the cases glslang does not emit for this project.
#include <cstdint>
#include <initializer_list>
#include <optional>
#include <vector>

namespace ppr::test {

enum : uint32_t { kUniformConstant = 0, kUniform = 2, kPushConstant = 9, kStorageBuffer = 12 };
enum : uint32_t { kDim2D = 1, kDimBuffer = 5, kDimSubpassData = 6 };
enum : uint32_t { kNoBlock = 0, kBlock = 2, kBufferBlock = 3 };

class SpirvAsm {
public:
    uint32_t id() { return next_++; }
    void op(uint32_t opcode, std::initializer_list<uint32_t> operands) {
        body_.push_back(static_cast<uint32_t>(operands.size() + 1) << 16 | opcode);
        body_.insert(body_.end(), operands);
    }
    uint32_t result(uint32_t opcode, std::initializer_list<uint32_t> rest) {  // OpType*: result id first
        const uint32_t r = id();
        std::vector<uint32_t> words{r};
        words.insert(words.end(), rest);
        body_.push_back(static_cast<uint32_t>(words.size() + 1) << 16 | opcode);
        body_.insert(body_.end(), words.begin(), words.end());
        return r;
    }

    uint32_t typeFloat() { return result(22, {32}); }
    uint32_t typeUint() { return result(21, {32, 0}); }
    uint32_t vector(uint32_t component, uint32_t n) { return result(23, {component, n}); }
    uint32_t matrix(uint32_t column, uint32_t n) { return result(24, {column, n}); }
    uint32_t constant(uint32_t value) {
        const uint32_t type = typeUint(), r = id();
        op(43, {type, r, value});
        return r;
    }
    uint32_t image(uint32_t dim, uint32_t sampled) { return result(25, {typeFloat(), dim, 0, 0, 0, sampled, 0}); }
    uint32_t sampledImage(uint32_t image) { return result(27, {image}); }
    uint32_t sampler() { return result(26, {}); }
    uint32_t accelerationStructure() { return result(5341, {}); }
    uint32_t array(uint32_t element, uint32_t length, uint32_t stride = 0) {
        const uint32_t len = constant(length), r = result(28, {element, len});
        if (stride) op(71, {r, 6, stride});
        return r;
    }
    uint32_t runtimeArray(uint32_t element) { return result(29, {element}); }
    // Members at the given byte offsets; `block` is kNoBlock, kBlock or kBufferBlock.
    uint32_t structOf(std::initializer_list<uint32_t> members, std::initializer_list<uint32_t> offsets, uint32_t block) {
        const uint32_t r = id();
        body_.push_back(static_cast<uint32_t>(members.size() + 2) << 16 | 30u);
        body_.push_back(r);
        body_.insert(body_.end(), members);
        uint32_t k = 0;
        for (uint32_t offset : offsets) op(72, {r, k++, 35, offset});
        if (block) op(71, {r, block});
        return r;
    }
    uint32_t variable(uint32_t type, uint32_t storage, std::optional<uint32_t> set = 0, std::optional<uint32_t> binding = std::nullopt) {
        const uint32_t pointer = result(32, {storage, type}), r = id();
        op(59, {pointer, r, storage});
        if (set) op(71, {r, 34, *set});
        if (binding) op(71, {r, 33, *binding});
        return r;
    }
    uint32_t resource(uint32_t type, uint32_t set, uint32_t binding, uint32_t storage = kUniformConstant) {
        return variable(type, storage, set, binding);
    }

    std::vector<uint32_t> words() const {
        std::vector<uint32_t> w{0x07230203u, 0x00010600u, 0u, next_, 0u};
        w.insert(w.end(), body_.begin(), body_.end());
        return w;
    }

private:
    uint32_t next_ = 1;
    std::vector<uint32_t> body_;
};

}  // namespace ppr::test
