#pragma once
// Clearing a colour image, two ways that leave the same bits:
// - transfer: vkCmdClearColorImage. On lavapipe a memset (0.2 ms at 1080p, against 8 ms for the
//   compute clear, whose image stores run as shader code on the CPU).
// - compute: clear_float.comp / clear_uint.comp. On an NVIDIA H100 the transfer clear runs through
//   the raster back-end at about 50 GB/s (0.32 ms for a 1080p rgba16f image, 1.19 ms at 4K) while a
//   compute pass writing the same bytes takes a few microseconds.
// FrameInputs::computeClear picks one (the app's `--set clear`, auto: compute unless the device is a
// CPU); addClearPass is how every pass clears.
#include "common/frame_inputs.hpp"
#include "graph/graph.hpp"
#include "shader/pipeline.hpp"

#include <string>

namespace ppr::passes {

class ImageClear {
public:
    explicit ImageClear(const vk::Context& ctx);
    // The cheaper method on this device (what `auto` means): compute, unless the device is a CPU.
    static bool computeIsCheaper(const vk::DeviceInfo& device);
    // One compute pass `passName` writing `value` over all of `image`; returns the cleared version.
    graph::ImageHandle addCompute(graph::RenderGraph& g, const std::string& passName, graph::ImageHandle image,
                                  const VkClearColorValue& value) const;

private:
    const vk::Context& ctx_;
    shader::Pipeline float_, uint_;
};

// A transfer clear, or ImageClear's compute clear when `in` asks for it. Returns the cleared version.
graph::ImageHandle addClearPass(graph::RenderGraph& g, const FrameInputs& in, const std::string& passName, graph::ImageHandle image,
                                const VkClearColorValue& value);

}  // namespace ppr::passes
