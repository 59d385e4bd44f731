#pragma once
// PPR step 1: the intermediate buffer (r32ui, one value per pixel), cleared to kPprClearValue with a
// transfer clear — on lavapipe 0.2 ms against 8 ms for a compute clear at 1080p.
#include "graph/graph.hpp"

namespace ppr::passes {

constexpr VkFormat kPprIntermediateFormat = VK_FORMAT_R32_UINT;

// Creates `name` at `extent` and adds the clear pass `passName`; returns the cleared version.
graph::ImageHandle addPprClearPass(graph::RenderGraph& g, const std::string& name, VkExtent2D extent, const std::string& passName = "ppr.clear");

}  // namespace ppr::passes
