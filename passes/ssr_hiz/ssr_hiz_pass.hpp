#pragma once
// Technique `ssr-hiz` (ssr_hiz.comp); the shared machinery is ssr_common/ssr_trace_pass.hpp.
#include "ssr_common/ssr_trace_pass.hpp"

#include <memory>

namespace ppr::passes {

std::unique_ptr<SsrTracePass> makeSsrHizPass(const vk::Context& ctx);

}  // namespace ppr::passes
