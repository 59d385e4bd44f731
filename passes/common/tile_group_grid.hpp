#pragma once
// Passes that give each screen tile `lanes` invocations and pack groupSize / lanes tiles into a
// workgroup (tiles.classify, ppr.reach) lay the workgroups out in rows of at most groupsPerRow: a
// 4096² frame at 64 invocations per tile needs 65 536 workgroups, beyond the 65 535 per dimension
// every device offers. The shader finds its group as gl_WorkGroupID.y * gl_NumWorkGroups.x + x.
#include <vulkan/vulkan.h>

#include <algorithm>
#include <cstdint>

namespace ppr::passes {

// The extent to dispatch in groups of groupSize (ComputePass::dispatch) for tileCount tiles.
inline VkExtent2D tileGroupGrid(uint32_t tileCount, uint32_t lanes, uint32_t groupSize, uint32_t groupsPerRow) {
    const uint32_t groups = (tileCount * lanes + groupSize - 1) / groupSize;
    const uint32_t perRow = std::min(groups, groupsPerRow);
    const uint32_t rows = (groups + perRow - 1) / perRow;
    return {perRow * groupSize, rows * groupSize};
}

}  // namespace ppr::passes
