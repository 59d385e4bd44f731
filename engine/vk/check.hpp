#pragma once
// Every VkResult goes through VK_CHECK: a failure throws with the call's text, file and line.
#include <vulkan/vulkan.h>

#include <stdexcept>
#include <string>

namespace ppr::vk {

const char* resultName(VkResult result);

[[noreturn]] void throwVkError(VkResult result, const char* expr, const char* file, int line);

}  // namespace ppr::vk

#define VK_CHECK(expr)                                                                   \
    do {                                                                                 \
        VkResult vk_check_result_ = (expr);                                              \
        if (vk_check_result_ < 0) ::ppr::vk::throwVkError(vk_check_result_, #expr, __FILE__, __LINE__); \
    } while (0)
