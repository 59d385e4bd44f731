#pragma once
// The reflection probe's one-time render: the shadow map, then per cube face the G-buffer and lighting
// passes from the probe's centre with a 90° square view (the same lit scene every frame draws, sky
// included), resampled into that face's layer of the cube (env_probe_store.comp). Added to a graph of
// its own that is recorded once (app/frame/environment_probe.hpp); nothing of it runs per frame.
#include "common/frame_inputs.hpp"
#include "gbuffer/gbuffer_pass.hpp"
#include "lighting/lighting_pass.hpp"
#include "shadow/shadow_pass.hpp"

#include <array>

namespace ppr::passes {

class EnvProbePass {
public:
    static constexpr VkFormat kFormat = VK_FORMAT_R16G16B16A16_SFLOAT;  // rgb radiance, a = distance (0: sky)
    static constexpr uint32_t kFaces = 6;

    EnvProbePass(const vk::Context& ctx, const ShadowPass& shadow, const GBufferPass& gbuffer, const LightingPass& lighting);
    // `faces[i]`: face i's frame inputs (faceView, kEnvProbeFaceSize² extent); `cube`: the cube imported
    // with a 2D-array view (storage). Returns its written version.
    graph::ImageHandle add(graph::RenderGraph& g, const std::array<FrameInputs, kFaces>& faces, uint32_t shadowRes,
                           graph::ImageHandle cube) const;
    // World → view of face i seen from `centre`: looking down the face's axis (+X −X +Y −Y +Z −Z); use
    // with a 90° square projection. Its roll is free: the store pass resamples through it.
    static glm::mat4 faceView(uint32_t face, const glm::vec3& centre);

private:
    const vk::Context& ctx_;
    const ShadowPass& shadow_;
    const GBufferPass& gbuffer_;
    const LightingPass& lighting_;
    shader::Pipeline store_;
};

}  // namespace ppr::passes
