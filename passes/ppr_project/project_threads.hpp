#pragma once
// The invocations per tile that --set project_threads offers: ppr_project.comp's specialization
// constant (ppr_project.h says which the device gets by default and why).
#include <array>
#include <cstdint>

namespace ppr::passes {

inline constexpr std::array<uint32_t, 4> kProjectThreadChoices{32, 64, 128, 256};

}  // namespace ppr::passes
