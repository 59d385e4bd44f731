#pragma once
// Copies an image into an imported host-visible buffer (capture / tests). A side effect: never culled.
#include "graph/graph.hpp"

namespace ppr::passes {

void addReadbackPass(graph::RenderGraph& g, const std::string& name, graph::ImageHandle image, graph::BufferHandle buffer);

}  // namespace ppr::passes
