#include "ssr_linear/ssr_linear_pass.hpp"

#include "ssr_linear_comp.h"

namespace ppr::passes {

std::unique_ptr<SsrTracePass> makeSsrLinearPass(const vk::Context& ctx) {
    return std::make_unique<SsrTracePass>(ctx, PPR_SPIRV(ssr_linear_comp), "ssr-linear", false);
}

}  // namespace ppr::passes
