#pragma once
// Transfer passes around the indirect dispatch lists (ppr_common/tiles.h TileDispatchArgs): an empty
// list before a pass appends to it, and its counts copied into the host-visible stats after.
#include "graph/graph.hpp"

#include <string>

namespace ppr::passes {

// One pass `passName`: the buffer's first TileDispatchArgs set to an empty list (x = 0, y = z = 1)
// and, with `zeroRest`, every byte after it zeroed (disjoint ranges: no barrier between the two).
// Returns the cleared version.
graph::BufferHandle addEmptyDispatchList(graph::RenderGraph& g, const std::string& passName, graph::BufferHandle buffer,
                                         bool zeroRest = false);

// One pass `passName`: `size` bytes of `src` from `srcOffset` into `dst` at `dstOffset` (a list's
// counts into the stats). Returns dst's new version.
graph::BufferHandle addCountCopy(graph::RenderGraph& g, const std::string& passName, graph::BufferHandle src, VkDeviceSize srcOffset,
                                 graph::BufferHandle dst, VkDeviceSize dstOffset, VkDeviceSize size);

}  // namespace ppr::passes
