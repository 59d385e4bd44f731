#pragma once
// The invocations per tile that --set reach_threads offers: ppr_reach.comp's specialization constant
// (ppr_reach.h says which the device gets by default and why).
#include <array>
#include <cstdint>

namespace ppr::passes {

inline constexpr std::array<uint32_t, 4> kReachThreadChoices{1, 4, 16, 64};

}  // namespace ppr::passes
