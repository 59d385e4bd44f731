#include "shader/layout_check.hpp"

#include <stdexcept>

namespace ppr::shader {

std::vector<VkDescriptorType> pushSetTypes(const ReflectedLayout& reflected, uint32_t pushConstantBytes, size_t extraSets,
                                           const std::string& pipeline) {
    const std::string who = "pipeline '" + pipeline + "'";
    if (reflected.pushConstantBytes && *reflected.pushConstantBytes != pushConstantBytes)
        throw std::logic_error(who + ": the shaders' push-constant block is " + std::to_string(*reflected.pushConstantBytes) +
                               " bytes, PipelineLayoutDesc::pushConstantBytes says " + std::to_string(pushConstantBytes));
    for (const auto& [set, bindings] : reflected.sets)
        if (set > extraSets && !bindings.empty())
            throw std::logic_error(who + ": the shaders use descriptor set " + std::to_string(set) + " but the layout provides sets 0.." +
                                   std::to_string(extraSets) + " (PipelineLayoutDesc::extraSets)");
    std::vector<VkDescriptorType> types;
    auto set0 = reflected.sets.find(0);
    if (set0 == reflected.sets.end()) return types;
    for (const auto& [binding, b] : set0->second) {
        if (binding != types.size())
            throw std::logic_error(who + ": set 0 declares binding " + std::to_string(binding) + " ('" + b.name + "') but no binding " +
                                   std::to_string(types.size()) + "; push descriptors are numbered in call order, so set 0 must run 0, 1, 2, ...");
        if (b.count != 1)
            throw std::logic_error(who + ": set 0 binding " + std::to_string(binding) + " ('" + b.name +
                                   "') is an array; push descriptors bind one descriptor per binding");
        types.push_back(b.type);
    }
    return types;
}

void checkBindings(std::string_view pipeline, std::string_view pass, std::span<const VkDescriptorType> expected,
                   std::span<const VkDescriptorType> given) {
    auto fail = [&](const std::string& why) {
        std::string who = pass.empty() ? "" : "pass '" + std::string(pass) + "' ";
        who += pass.empty() ? "pipeline '" + std::string(pipeline) + "'" : "(pipeline '" + std::string(pipeline) + "')";
        throw std::logic_error(who + ": " + why + " (bindings are numbered in call order)");
    };
    for (size_t i = 0; i < expected.size() && i < given.size(); ++i)
        if (expected[i] != given[i])
            fail("binding " + std::to_string(i) + ": the shader expects " + descriptorTypeName(expected[i]) + ", given " +
                 descriptorTypeName(given[i]));
    if (given.size() < expected.size())
        fail(std::to_string(given.size()) + " bindings given, the shader expects " + std::to_string(expected.size()) + "; binding " +
             std::to_string(given.size()) + " (" + descriptorTypeName(expected[given.size()]) + ") is missing");
    if (given.size() > expected.size())
        fail(std::to_string(given.size()) + " bindings given, the shader expects " + std::to_string(expected.size()) + "; binding " +
             std::to_string(expected.size()) + " (" + descriptorTypeName(given[expected.size()]) + ") has no place");
}

}  // namespace ppr::shader
