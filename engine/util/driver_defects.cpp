#include "util/driver_defects.hpp"

namespace ppr::util {

std::string lavapipeWidthWarning(std::string_view deviceType, std::string_view deviceName, uint32_t subgroupSize) {
    constexpr uint32_t kTestedLanes = 8;  // lavapipe's default on x86-64 (256-bit rows)
    if (deviceType != "cpu" || !deviceName.starts_with("llvmpipe") || subgroupSize == kTestedLanes) return "";
    return "llvmpipe runs " + std::to_string(subgroupSize) + "-lane rows here (LP_NATIVE_VECTOR_WIDTH=" + std::to_string(subgroupSize * 32) +
           "), where it projects only half of every tile in PPR; unset LP_NATIVE_VECTOR_WIDTH for its default 8 lanes, the width this project is tested at";
}

}  // namespace ppr::util
