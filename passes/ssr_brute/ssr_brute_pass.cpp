#include "ssr_brute/ssr_brute_pass.hpp"

#include "ssr_brute_comp.h"

namespace ppr::passes {

std::unique_ptr<SsrTracePass> makeSsrBrutePass(const vk::Context& ctx) {
    return std::make_unique<SsrTracePass>(ctx, PPR_SPIRV(ssr_brute_comp), "ssr-brute", false);
}

}  // namespace ppr::passes
