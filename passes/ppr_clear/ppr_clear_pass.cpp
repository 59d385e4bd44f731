#include "ppr_clear/ppr_clear_pass.hpp"

#include "common/clear_pass.hpp"
#include "ppr_common/encoding.h"

namespace ppr::passes {

graph::ImageHandle addPprClearPass(graph::RenderGraph& g, const FrameInputs& in, const std::string& name, VkExtent2D extent, const std::string& passName) {
    VkClearColorValue clear{};
    clear.uint32[0] = gpu::kPprClearValue;
    return addClearPass(g, in, passName, g.createImage(name, {extent.width, extent.height, kPprIntermediateFormat, 1}), clear);
}

}  // namespace ppr::passes
