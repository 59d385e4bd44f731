#pragma once
// Opaque geometry into the G-buffer (layout in gbuffer.h), after a depth-only pre-pass when
// FrameInputs::depthPrepass asks for one: the G-buffer's fragment shader (three texture lookups, the
// frame's costliest on lavapipe) then runs once per visible pixel instead of once per layer drawn
// over it, with the same images.
#include "common/frame_inputs.hpp"
#include "graph/graph.hpp"

namespace ppr::passes {

struct GBuffer {
    graph::ImageHandle depth, normal, albedo, material, reflector;
    graph::ImageHandle emissive;  // invalid when no opaque material emits (GBufferPass::emissive_)
};

class GBufferPass {
public:
    static constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT;
    static constexpr VkFormat kNormalFormat = VK_FORMAT_R16G16B16A16_SFLOAT;
    static constexpr VkFormat kAlbedoFormat = VK_FORMAT_R8G8B8A8_SRGB;
    static constexpr VkFormat kMaterialFormat = VK_FORMAT_R8G8B8A8_UNORM;
    static constexpr VkFormat kReflectorFormat = VK_FORMAT_R16_UINT;
    static constexpr VkFormat kEmissiveFormat = VK_FORMAT_B10G11R11_UFLOAT_PACK32;
    // The pre-pass's depth bias (toward far): steps of the depth format at the primitive's largest
    // depth, plus a hundredth of a pixel's depth slope, so that the shading pass's own depth of the
    // nearest fragment lies strictly in front of it, whatever each pipeline's rounding.
    static constexpr float kPrepassBiasSteps = 4.0f;
    static constexpr float kPrepassBiasSlope = 0.01f;

    GBufferPass(const vk::Context& ctx, const gpu::GpuScene& scene);
    // `targets`: existing images to draw into (new versions), e.g. the planar reference reusing one
    // G-buffer for every mirrored view; null = new transient images named "<name>.depth" etc.
    GBuffer add(graph::RenderGraph& g, const FrameInputs& in, const std::string& name = "gbuffer", const GBuffer* targets = nullptr) const;
    // New transient G-buffer images named "<name>.depth", "<name>.normal", ...
    GBuffer createTargets(graph::RenderGraph& g, const std::string& name, VkExtent2D extent) const;

private:
    // The opaque, unmasked draws' depth into `depth` (cleared first); returns its new version.
    graph::ImageHandle addPrepass(graph::RenderGraph& g, const FrameInputs& in, const std::string& name, graph::ImageHandle depth) const;
    const vk::Context& ctx_;
    // Whether the G-buffer has its emissive target: only for a scene with an opaque material that emits
    // (scene::Scene::opaqueMaterialEmits). Without it the pass writes four targets and the lighting
    // adds nothing, which is what it added before: the images are the same, the target's writes and
    // reads saved (docs/performance.md).
    bool emissive_;
    shader::Pipeline pipeline_, prepassPipeline_;
};

}  // namespace ppr::passes
