#pragma once
// Technique `ssr-brute` (ssr_brute.comp); the shared machinery is ssr_common/ssr_trace_pass.hpp.
#include "ssr_common/ssr_trace_pass.hpp"

#include <memory>

namespace ppr::passes {

std::unique_ptr<SsrTracePass> makeSsrBrutePass(const vk::Context& ctx);

}  // namespace ppr::passes
