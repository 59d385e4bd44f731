#pragma once
// The invocations per coarsest cell that --set hiz_threads offers: hiz_build.comp's specialization
// constant (hiz.h says which the device gets by default and why). Each a power of four: square blocks.
#include <array>
#include <cstdint>

namespace ppr::passes {

inline constexpr std::array<uint32_t, 3> kHizThreadChoices{16, 64, 256};

}  // namespace ppr::passes
