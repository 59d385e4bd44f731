#pragma once
// Opaque geometry into the G-buffer (layout in gbuffer.h).
#include "common/frame_inputs.hpp"
#include "graph/graph.hpp"

namespace ppr::passes {

struct GBuffer {
    graph::ImageHandle depth, normal, albedo, material, reflector;
};

class GBufferPass {
public:
    static constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT;
    static constexpr VkFormat kNormalFormat = VK_FORMAT_R16G16B16A16_SFLOAT;
    static constexpr VkFormat kAlbedoFormat = VK_FORMAT_R8G8B8A8_SRGB;
    static constexpr VkFormat kMaterialFormat = VK_FORMAT_R8G8B8A8_UNORM;
    static constexpr VkFormat kReflectorFormat = VK_FORMAT_R16_UINT;

    GBufferPass(const vk::Context& ctx, const gpu::GpuScene& scene);
    GBuffer add(graph::RenderGraph& g, const FrameInputs& in) const;

private:
    const vk::Context& ctx_;
    shader::Pipeline pipeline_;
};

}  // namespace ppr::passes
