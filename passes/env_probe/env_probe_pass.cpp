#include "env_probe/env_probe_pass.hpp"

#include "common/compute_pass.hpp"
#include "env_probe/env_probe.h"
#include "env_probe_store_comp.h"

#include <glm/gtc/matrix_transform.hpp>

namespace ppr::passes {

EnvProbePass::EnvProbePass(const vk::Context& ctx, const ShadowPass& shadow, const GBufferPass& gbuffer, const LightingPass& lighting)
    : ctx_(ctx), shadow_(shadow), gbuffer_(gbuffer), lighting_(lighting) {
    shader::PipelineLayoutDesc layout;
    layout.pushConstantBytes = sizeof(gpu::EnvProbeStorePush);
    store_ = shader::createComputePipeline(ctx, PPR_SPIRV(env_probe_store_comp), layout, "env.probe.store");
}

glm::mat4 EnvProbePass::faceView(uint32_t face, const glm::vec3& centre) {
    static const glm::vec3 kAxis[kFaces] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    const glm::vec3 up = face == 2 ? glm::vec3(0, 0, -1) : face == 3 ? glm::vec3(0, 0, 1) : glm::vec3(0, 1, 0);
    return glm::lookAt(centre, centre + kAxis[face], up);
}

graph::ImageHandle EnvProbePass::add(graph::RenderGraph& g, const std::array<FrameInputs, kFaces>& faces, uint32_t shadowRes,
                                     graph::ImageHandle cube) const {
    const VkExtent2D extent = faces[0].extent;
    const graph::ImageHandle shadowMap = shadow_.add(g, faces[0], shadowRes);
    // One G-buffer and one colour image, rewritten face after face (as the planar reference does per plane).
    GBuffer gb = gbuffer_.createTargets(g, "env.probe.gbuffer", extent);
    graph::ImageHandle lit = g.createImage("env.probe.color", {extent.width, extent.height, LightingPass::kColorFormat, 1});
    for (uint32_t face = 0; face < kFaces; ++face) {
        const FrameInputs& in = faces[face];
        const std::string n = std::to_string(face);
        gb = gbuffer_.add(g, in, "env.probe.gbuffer." + n, &gb);
        lit = lighting_.add(g, in, gb, shadowMap, "env.probe.lighting." + n, lit);
        ComputePass(g, ctx_, "env.probe.store." + n, store_)
            .uniform(in.frameConstants, in.frameConstantsOffset, in.frameConstantsSize)
            .sampled(lit, in.samplers->nearestClamp)
            .sampled(gb.depth, in.samplers->nearestClamp)
            .storageReadWrite(cube, &cube)  // the other faces' layers are kept
            .push(gpu::EnvProbeStorePush{face, extent.width})
            .dispatch(extent, gpu::kEnvProbeGroupSize);
    }
    return cube;
}

}  // namespace ppr::passes
