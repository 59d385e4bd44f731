#pragma once
// PPR reflection pass (ppr_reflect.comp): intermediate buffer + lit scene → reflection image.
#include "common/frame_inputs.hpp"
#include "graph/graph.hpp"

namespace ppr::passes {

class PprReflectPass {
public:
    static constexpr VkFormat kReflectionFormat = VK_FORMAT_R16G16B16A16_SFLOAT;
    explicit PprReflectPass(const vk::Context& ctx);
    // flags: ppr_reflect.h kPpr* toggles; debugView: frame.h kDebug* (intermediate / holes draw here).
    graph::ImageHandle add(graph::RenderGraph& g, const FrameInputs& in, graph::ImageHandle intermediate, graph::ImageHandle sceneColor,
                           graph::ImageHandle reflectorIds, uint32_t flags, uint32_t debugView) const;

private:
    const vk::Context& ctx_;
    shader::Pipeline pipeline_;
};

}  // namespace ppr::passes
