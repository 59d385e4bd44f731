#include "ppr_clear/ppr_clear_pass.hpp"

#include "ppr_common/encoding.h"

namespace ppr::passes {

void queuePprClear(graph::RenderGraph& g, TransferBatch& batch, const std::string& name, VkExtent2D extent, const std::string& computePassName,
                   graph::ImageHandle* cleared) {
    VkClearColorValue clear{};
    clear.uint32[0] = gpu::kPprClearValue;
    batch.clearImage(g.createImage(name, {extent.width, extent.height, kPprIntermediateFormat, 1}), clear, computePassName, cleared);
}

}  // namespace ppr::passes
