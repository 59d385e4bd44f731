#pragma once
// Opaque geometry into the G-buffer (layout in gbuffer.h).
#include "common/frame_inputs.hpp"
#include "graph/graph.hpp"

namespace ppr::passes {

struct GBuffer {
    graph::ImageHandle depth, normal, albedo, material, reflector, emissive;
};

class GBufferPass {
public:
    static constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT;
    static constexpr VkFormat kNormalFormat = VK_FORMAT_R16G16B16A16_SFLOAT;
    static constexpr VkFormat kAlbedoFormat = VK_FORMAT_R8G8B8A8_SRGB;
    static constexpr VkFormat kMaterialFormat = VK_FORMAT_R8G8B8A8_UNORM;
    static constexpr VkFormat kReflectorFormat = VK_FORMAT_R16_UINT;
    static constexpr VkFormat kEmissiveFormat = VK_FORMAT_B10G11R11_UFLOAT_PACK32;

    GBufferPass(const vk::Context& ctx, const gpu::GpuScene& scene);
    // `targets`: existing images to draw into (new versions), e.g. the planar reference reusing one
    // G-buffer for every mirrored view; null = new transient images named "<name>.depth" etc.
    GBuffer add(graph::RenderGraph& g, const FrameInputs& in, const std::string& name = "gbuffer", const GBuffer* targets = nullptr) const;
    // New transient G-buffer images named "<name>.depth", "<name>.normal", ...
    static GBuffer createTargets(graph::RenderGraph& g, const std::string& name, VkExtent2D extent);

private:
    const vk::Context& ctx_;
    shader::Pipeline pipeline_;
};

}  // namespace ppr::passes
