#include "vk/check.hpp"

#include <sstream>

namespace ppr::vk {

const char* resultName(VkResult result) {
    switch (result) {
#define PPR_RESULT(x) \
    case x: return #x;
        PPR_RESULT(VK_SUCCESS)
        PPR_RESULT(VK_NOT_READY)
        PPR_RESULT(VK_TIMEOUT)
        PPR_RESULT(VK_INCOMPLETE)
        PPR_RESULT(VK_SUBOPTIMAL_KHR)
        PPR_RESULT(VK_ERROR_OUT_OF_HOST_MEMORY)
        PPR_RESULT(VK_ERROR_OUT_OF_DEVICE_MEMORY)
        PPR_RESULT(VK_ERROR_INITIALIZATION_FAILED)
        PPR_RESULT(VK_ERROR_DEVICE_LOST)
        PPR_RESULT(VK_ERROR_MEMORY_MAP_FAILED)
        PPR_RESULT(VK_ERROR_LAYER_NOT_PRESENT)
        PPR_RESULT(VK_ERROR_EXTENSION_NOT_PRESENT)
        PPR_RESULT(VK_ERROR_FEATURE_NOT_PRESENT)
        PPR_RESULT(VK_ERROR_INCOMPATIBLE_DRIVER)
        PPR_RESULT(VK_ERROR_TOO_MANY_OBJECTS)
        PPR_RESULT(VK_ERROR_FORMAT_NOT_SUPPORTED)
        PPR_RESULT(VK_ERROR_FRAGMENTED_POOL)
        PPR_RESULT(VK_ERROR_OUT_OF_POOL_MEMORY)
        PPR_RESULT(VK_ERROR_SURFACE_LOST_KHR)
        PPR_RESULT(VK_ERROR_NATIVE_WINDOW_IN_USE_KHR)
        PPR_RESULT(VK_ERROR_OUT_OF_DATE_KHR)
#undef PPR_RESULT
        default: return "VK_ERROR_(unknown)";
    }
}

void throwVkError(VkResult result, const char* expr, const char* file, int line) {
    std::ostringstream os;
    os << "vulkan: " << expr << " failed with " << resultName(result) << " (" << file << ":" << line << ")";
    throw std::runtime_error(os.str());
}

}  // namespace ppr::vk
