#pragma once
// The invocations per 16×16 tile that --set taa_threads offers: the TAA shaders' specialization constant
// (taa.h says which the device gets by default and why).
#include <array>
#include <cstdint>

namespace ppr::passes {

inline constexpr std::array<uint32_t, 3> kTaaThreadChoices{16, 64, 256};

}  // namespace ppr::passes
