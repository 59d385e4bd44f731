#pragma once
// PPR step 1: the intermediate buffer (r32ui, one value per pixel), cleared to kPprClearValue the
// way FrameInputs asks (common/clear_pass.hpp: transfer or compute, whichever the device does faster).
#include "common/frame_inputs.hpp"
#include "graph/graph.hpp"

namespace ppr::passes {

constexpr VkFormat kPprIntermediateFormat = VK_FORMAT_R32_UINT;

// Creates `name` at `extent` and adds the clear pass `passName`; returns the cleared version.
graph::ImageHandle addPprClearPass(graph::RenderGraph& g, const FrameInputs& in, const std::string& name, VkExtent2D extent, const std::string& passName = "ppr.clear");

}  // namespace ppr::passes
