#pragma once
// Checks between a pipeline's reflected layout and the C++ that creates and binds it. Pure logic (no
// device), so that the checks are unit-tested; every message names the pipeline (and the pass).
#include "shader/spirv_reflect.hpp"

#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace ppr::shader {

// Set 0's descriptor types in binding order, as the push-descriptor layout takes them. Throws
// std::logic_error naming `pipeline` when set 0 has a gap (bindings are numbered in call order, so
// they must run 0, 1, 2, ...) or an array, when the shaders use a set above 0 that `extraSets` does not
// provide, or when the shaders' push-constant block size differs from `pushConstantBytes`.
std::vector<VkDescriptorType> pushSetTypes(const ReflectedLayout& reflected, uint32_t pushConstantBytes, size_t extraSets,
                                           const std::string& pipeline);

// Throws std::logic_error when the bindings a pass supplies (in call order) differ in number or type
// from the pipeline's set 0, naming the pass (may be empty), the pipeline, the binding number and
// both types: a wrong call order becomes a clear error instead of a validation message.
void checkBindings(std::string_view pipeline, std::string_view pass, std::span<const VkDescriptorType> expected,
                   std::span<const VkDescriptorType> given);

}  // namespace ppr::shader
