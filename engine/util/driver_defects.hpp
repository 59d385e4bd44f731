#pragma once
// Drivers that compute wrongly in a configuration a user can choose: the warning line to show.

#include <cstdint>
#include <string>
#include <string_view>

namespace ppr::util {

// lavapipe (llvmpipe) compiles shaders for SIMD rows of LP_NATIVE_VECTOR_WIDTH / 32 lanes, which is
// also its subgroup size: 8 by default on x86-64. At 16 lanes (LP_NATIVE_VECTOR_WIDTH=512, which a
// CPU with AVX-512 accepts) Mesa 25.0's code stops storing from the upper 8 lanes of each row after a
// branch in PPR's per-tile culling, so the left half of every tile alone is projected (puddles
// vanish: docs/performance.md, "16 lanes on lavapipe"); at 4 and 32 lanes it crashes. The warning
// for a CPU device named llvmpipe whose subgroup size is not 8, else "".
std::string lavapipeWidthWarning(std::string_view deviceType, std::string_view deviceName, uint32_t subgroupSize);

}  // namespace ppr::util
