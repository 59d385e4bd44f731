#include "ssr_hiz/ssr_hiz_pass.hpp"

#include "ssr_hiz_comp.h"

namespace ppr::passes {

std::unique_ptr<SsrTracePass> makeSsrHizPass(const vk::Context& ctx) {
    return std::make_unique<SsrTracePass>(ctx, PPR_SPIRV(ssr_hiz_comp), "ssr-hiz", true);
}

}  // namespace ppr::passes
