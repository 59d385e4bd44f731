#pragma once
// The invocations per tile that --set classify_threads offers: tile_classify.comp's specialization
// constant (tile_classify.h says which the device gets by default and why).
#include <array>
#include <cstdint>

namespace ppr::passes {

inline constexpr std::array<uint32_t, 3> kClassifyThreadChoices{1, 16, 64};

}  // namespace ppr::passes
