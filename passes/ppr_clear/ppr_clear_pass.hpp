#pragma once
// PPR step 1: the intermediate buffer (r32ui, one value per pixel), cleared to kPprClearValue the
// way FrameInputs asks (common/clear_pass.hpp: transfer or compute, whichever the device does
// faster), in the technique's batch of clears (common/transfer_batch.hpp).
#include "common/transfer_batch.hpp"
#include "graph/graph.hpp"

#include <string>

namespace ppr::passes {

constexpr VkFormat kPprIntermediateFormat = VK_FORMAT_R32_UINT;

// Creates `name` at `extent` and queues its clear in `batch` (`computePassName`: its own pass where
// clears run as compute); `cleared` after batch.add().
void queuePprClear(graph::RenderGraph& g, TransferBatch& batch, const std::string& name, VkExtent2D extent, const std::string& computePassName,
                   graph::ImageHandle* cleared);

}  // namespace ppr::passes
