#pragma once
// PPR projection pass (ppr_project.comp): scatters every pixel's offset into the intermediate buffer.
#include "common/frame_inputs.hpp"
#include "graph/graph.hpp"

namespace ppr::passes {

struct ReflectorBinding {  // the reflector buffers of the frame's slot (common/reflector_buffer.hpp)
    VkBuffer reflectors = VK_NULL_HANDLE;
    VkBuffer order = VK_NULL_HANDLE;
    uint32_t count = 0;
};

class PprProjectPass {
public:
    explicit PprProjectPass(const vk::Context& ctx);
    // Returns the intermediate buffer's new version.
    graph::ImageHandle add(graph::RenderGraph& g, const FrameInputs& in, graph::ImageHandle depth, const ReflectorBinding& reflectors,
                           graph::ImageHandle intermediate) const;

private:
    const vk::Context& ctx_;
    shader::Pipeline pipeline_;
};

}  // namespace ppr::passes
