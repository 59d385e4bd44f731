#include "planar/planar_pass.hpp"

#include "common/compute_pass.hpp"
#include "planar/planar.h"
#include "planar_resolve_comp.h"
#include "ppr_reflect/ppr_reflect_pass.hpp"

namespace ppr::passes {

PlanarPass::PlanarPass(const vk::Context& ctx, const GBufferPass& gbuffer, const LightingPass& lighting)
    : ctx_(ctx), gbuffer_(gbuffer), lighting_(lighting) {
    shader::PipelineLayoutDesc layout;
    layout.pushBindings = {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER,         VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER,
                           VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
                           VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
                           VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
                           VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,         VK_DESCRIPTOR_TYPE_STORAGE_IMAGE};
    layout.pushConstantBytes = sizeof(gpu::PlanarResolvePush);
    resolve_ = shader::createComputePipeline(ctx, PPR_SPIRV(planar_resolve_comp), layout, "planar.resolve");
}

graph::ImageHandle PlanarPass::add(graph::RenderGraph& g, const FrameInputs& in, const GBuffer& gb, graph::ImageHandle shadowMap,
                                   const std::vector<PlanarView>& views, VkBuffer reflectors) const {
    // Start from "no reflection" everywhere; each plane group's resolve fills its own pixels.
    struct ClearData {
        graph::ImageHandle image;
    };
    const graph::ImageHandle created =
        g.createImage("reflection", {in.extent.width, in.extent.height, PprReflectPass::kReflectionFormat, 1});
    graph::ImageHandle reflection = g.addPass<ClearData>(
                                         "planar.clear", graph::QueueKind::Transfer,
                                         [&](graph::PassBuilder& b, ClearData& d) { d.image = b.transferDst(created); },
                                         [](const ClearData& d, graph::PassContext& pc) {
                                             const VkClearColorValue zero{};
                                             const VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
                                             vkCmdClearColorImage(pc.cmd(), pc.image(d.image), pc.layout(d.image), &zero, 1, &range);
                                         })
                                         .image;

    // One mirrored G-buffer and colour image, rewritten view after view (the graph orders the reuse),
    // instead of a full set per plane.
    if (views.empty()) return reflection;
    GBuffer mirrored = GBufferPass::createTargets(g, "planar.gbuffer", in.extent);
    graph::ImageHandle mirroredColor = g.createImage("planar.color", {in.extent.width, in.extent.height, LightingPass::kColorFormat, 1});
    for (const PlanarView& v : views) {
        const std::string suffix = "." + std::to_string(v.planeGroup);
        mirrored = gbuffer_.add(g, v.in, "planar.gbuffer" + suffix, &mirrored);
        mirroredColor = lighting_.add(g, v.in, mirrored, shadowMap, "planar.lighting" + suffix, mirroredColor);
        gpu::PlanarResolvePush push{};
        push.planeGroup = v.planeGroup;
        ComputePass(g, ctx_, "planar.resolve" + suffix, resolve_)
            .uniform(in.frameConstants, in.frameConstantsOffset, in.frameConstantsSize)
            .uniform(v.in.frameConstants, v.in.frameConstantsOffset, v.in.frameConstantsSize)
            .sampled(mirroredColor, in.samplers->nearestClamp)
            .sampled(mirrored.depth, in.samplers->nearestClamp)
            .sampled(mirrored.normal, in.samplers->nearestClamp)
            .sampled(mirrored.reflector, in.samplers->nearestClamp)
            .sampled(gb.depth, in.samplers->nearestClamp)
            .sampled(gb.reflector, in.samplers->nearestClamp)
            .hostStorage(reflectors)
            .storageReadWrite(reflection, &reflection)
            .push(push)
            .dispatch(in.extent, gpu::kPlanarGroupSize);
    }
    return reflection;
}

}  // namespace ppr::passes
