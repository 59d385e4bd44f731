#pragma once
// Builds the depth hierarchy (hiz.h) from the G-buffer depth: levels 1.. in one pass, "hiz.build"
// (level 0 is the depth buffer itself).
#include "common/frame_inputs.hpp"
#include "common/workgroup_widths.hpp"
#include "graph/graph.hpp"

#include <optional>

namespace ppr::passes {

struct HizAtlas {
    graph::ImageHandle image;  // r32f, hizAtlasSize(hizPaddedSize(screen))
    uint32_t levels = 0;
};

class HizPass {
public:
    static constexpr VkFormat kFormat = VK_FORMAT_R32_SFLOAT;
    explicit HizPass(const vk::Context& ctx);
    // The atlas image for this frame's extent, unwritten (add() makes its own when not given one).
    static graph::ImageHandle createAtlas(graph::RenderGraph& g, const FrameInputs& in);
    // threads: invocations per coarsest cell (hiz_threads.hpp), 0 for the device's default.
    // fineLevels: an atlas in which levels 1..kHizTileLevel of every 16x16 tile of the screen are
    // already stored (PPR's reach pass): only the padding and the levels above are built.
    HizAtlas add(graph::RenderGraph& g, const FrameInputs& in, graph::ImageHandle depth, uint32_t threads,
                 std::optional<graph::ImageHandle> fineLevels = std::nullopt) const;
    static uint32_t autoThreads(const vk::DeviceInfo& device);

private:
    const vk::Context& ctx_;
    WidthPipelines pipelines_;
    WidthPipelines abovePipelines_;  // kFineLevelsBuilt
};

}  // namespace ppr::passes
