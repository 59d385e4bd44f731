#pragma once
// Technique `ssr-lowq` (ssr_lowq.comp); the shared machinery is ssr_common/ssr_trace_pass.hpp.
#include "ssr_common/ssr_trace_pass.hpp"

#include <memory>

namespace ppr::passes {

std::unique_ptr<SsrTracePass> makeSsrLowqPass(const vk::Context& ctx);

}  // namespace ppr::passes
