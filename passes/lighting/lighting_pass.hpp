#pragma once
// Deferred lighting: one directional light with PCF shadows + hemisphere ambient → HDR scene colour.
#include "common/frame_inputs.hpp"
#include "gbuffer/gbuffer_pass.hpp"

namespace ppr::passes {

class LightingPass {
public:
    static constexpr VkFormat kColorFormat = VK_FORMAT_R16G16B16A16_SFLOAT;
    explicit LightingPass(const vk::Context& ctx);
    // `target`: an existing image to write (a new version of it), e.g. the planar reference reusing one
    // image for every mirrored view; invalid = a new transient "sceneColor".
    graph::ImageHandle add(graph::RenderGraph& g, const FrameInputs& in, const GBuffer& gb, graph::ImageHandle shadowMap,
                           const std::string& name = "lighting", graph::ImageHandle target = {}) const;

private:
    const vk::Context& ctx_;
    // With the G-buffer's emissive target added, and without one (GBuffer::emissive invalid).
    shader::Pipeline pipeline_, noEmissivePipeline_;
};

}  // namespace ppr::passes
