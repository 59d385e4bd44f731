#include "ssr_lowq/ssr_lowq_pass.hpp"

#include "ssr_lowq_comp.h"

namespace ppr::passes {

std::unique_ptr<SsrTracePass> makeSsrLowqPass(const vk::Context& ctx) {
    return std::make_unique<SsrTracePass>(ctx, PPR_SPIRV(ssr_lowq_comp), "ssr-lowq", false);
}

}  // namespace ppr::passes
