#pragma once
// Technique `ssr-linear` (ssr_linear.comp); the shared machinery is ssr_common/ssr_trace_pass.hpp.
#include "ssr_common/ssr_trace_pass.hpp"

#include <memory>

namespace ppr::passes {

std::unique_ptr<SsrTracePass> makeSsrLinearPass(const vk::Context& ctx);

}  // namespace ppr::passes
