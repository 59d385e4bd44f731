#include "common/frame_inputs.hpp"

#include "gpu/scene_data.h"

#include <cstddef>

namespace ppr::passes {

std::vector<VkVertexInputAttributeDescription> sceneVertexAttributes(bool positionOnly) {
    using scene::Vertex;
    std::vector<VkVertexInputAttributeDescription> a = {
        {0, 0, VK_FORMAT_R32G32B32_SFLOAT, static_cast<uint32_t>(offsetof(Vertex, position))}};
    if (!positionOnly) {
        a.push_back({1, 0, VK_FORMAT_R32G32B32_SFLOAT, static_cast<uint32_t>(offsetof(Vertex, normal))});
        a.push_back({2, 0, VK_FORMAT_R32G32B32A32_SFLOAT, static_cast<uint32_t>(offsetof(Vertex, tangent))});
        a.push_back({3, 0, VK_FORMAT_R32G32_SFLOAT, static_cast<uint32_t>(offsetof(Vertex, uv0))});
        a.push_back({4, 0, VK_FORMAT_R16G16B16A16_UNORM, static_cast<uint32_t>(offsetof(Vertex, color))});
    }
    return a;
}

void drawUnmaskedDepth(const vk::Context& ctx, VkCommandBuffer cmd, const shader::Pipeline& pipeline, const FrameInputs& in,
                       gpu::GpuScene::Subset subset) {
    pipeline.bind(cmd);
    shader::PushDescriptors(ctx)
        .uniformBuffer(in.frameConstants, in.frameConstantsOffset, in.frameConstantsSize)
        .storageBuffer(in.draws)
        .push(cmd, pipeline);
    in.scene->drawOpaque(cmd, false, subset, [&](uint32_t i) { pipeline.pushConstants(cmd, gpu::DrawPush{i, 0, 0, 0}); });
}

}  // namespace ppr::passes
