#pragma once
// The descriptor layout a shader declares, read from its SPIR-V, so that the GLSL `layout(set, binding)`
// lines are the only place a pass spells its bindings. A small self-written parser: it knows the
// instructions glslang emits for descriptors and push-constant blocks, nothing more.
#include <vulkan/vulkan.h>

#include <cstdint>
#include <map>
#include <optional>
#include <span>
#include <string>

namespace ppr::shader {

struct ReflectedBinding {
    VkDescriptorType type = VK_DESCRIPTOR_TYPE_MAX_ENUM;
    uint32_t count = 1;  // descriptor array size; 0 for a runtime-sized array (bindless)
    std::string name;    // the GLSL variable (or block) name, for error messages
};

struct ReflectedLayout {
    std::map<uint32_t, std::map<uint32_t, ReflectedBinding>> sets;  // set → binding → descriptor
    std::optional<uint32_t> pushConstantBytes;  // furthest byte a push-constant block member reaches
};

// Reads one stage's bindings. `what` names the shader in error messages; malformed SPIR-V (wrong
// magic, truncated or inconsistent instructions) throws std::runtime_error, it never reads out of range.
ReflectedLayout reflectSpirv(std::span<const uint32_t> words, const std::string& what);

// Adds a further stage's bindings to `into` (vertex + fragment). A binding both stages declare must
// agree on type and count; the push-constant size is the larger of the two.
void mergeStage(ReflectedLayout& into, const ReflectedLayout& stage, const std::string& what);

// "COMBINED_IMAGE_SAMPLER", ... for messages.
const char* descriptorTypeName(VkDescriptorType type);

}  // namespace ppr::shader
