#include "planar/planar_pass.hpp"

#include "common/clear_pass.hpp"
#include "common/compute_pass.hpp"
#include "planar/planar.h"
#include "glass_reflect/glass_reflect_pass.hpp"
#include "planar_glass_resolve_comp.h"
#include "planar_resolve_comp.h"
#include "ppr_reflect/ppr_reflect_pass.hpp"

namespace ppr::passes {

PlanarPass::PlanarPass(const vk::Context& ctx, const GBufferPass& gbuffer, const LightingPass& lighting)
    : ctx_(ctx), gbuffer_(gbuffer), lighting_(lighting) {
    shader::PipelineLayoutDesc layout;
    layout.pushConstantBytes = sizeof(gpu::PlanarResolvePush);
    resolve_ = shader::createComputePipeline(ctx, PPR_SPIRV(planar_resolve_comp), layout, "planar.resolve");
    shader::PipelineLayoutDesc glassLayout;
    glassLayout.pushConstantBytes = sizeof(gpu::PlanarGlassPush);
    glassResolve_ = shader::createComputePipeline(ctx, PPR_SPIRV(planar_glass_resolve_comp), glassLayout, "planar.glass");
}

PlanarOutputs PlanarPass::add(graph::RenderGraph& g, const FrameInputs& in, const GBuffer& gb, graph::ImageHandle shadowMap,
                              const std::vector<PlanarView>& views, PlanarReflectors reflectors, const PlanarGlass* glass) const {
    // Start from "no reflection" everywhere; each plane group's resolve fills its own pixels.
    PlanarOutputs out;
    graph::ImageHandle& reflection = out.reflection;
    reflection = addClearPass(
        g, in, "planar.clear", g.createImage("planar.reflection", {in.extent.width, in.extent.height, PprReflectPass::kReflectionFormat, 1}), {});
    out.path = addClearPass(g, in, "planar.distance.clear", g.createImage("planar.distance", {in.extent.width, in.extent.height, kPathFormat, 1}), {});
    if (glass) {
        const uint32_t size = glass->atlasSize;
        out.glass = addClearPass(g, in, "planar.glass.clear", g.createImage("planar.glass", {size, size, GlassReflectPass::kFormat, 1}), {});
    }
    if (views.empty()) return out;
    GBuffer mirrored = gbuffer_.createTargets(g, "planar.gbuffer", in.extent);
    graph::ImageHandle mirroredColor = g.createImage("planar.color", {in.extent.width, in.extent.height, LightingPass::kColorFormat, 1});
    for (const PlanarView& v : views) {
        // Pass names "planar.<step>.<plane group>", one timing row per plane.
        const std::string plane = std::to_string(v.planeGroup);
        mirrored = gbuffer_.add(g, v.in, "planar.gbuffer." + plane, &mirrored);
        mirroredColor = lighting_.add(g, v.in, mirrored, shadowMap, "planar.lighting." + plane, mirroredColor);
        // Both resolves read the main and mirrored constants, the mirrored view and the main depth
        // first (planar_visibility.glsl), in this order.
        auto resolvePass = [&](const std::string& name, const shader::Pipeline& pipeline) {
            ComputePass pass(g, ctx_, name, pipeline);
            pass.uniform(in.frameConstants, in.frameConstantsOffset, in.frameConstantsSize)
                .uniform(v.in.frameConstants, v.in.frameConstantsOffset, v.in.frameConstantsSize)
                .sampled(mirroredColor, in.samplers->nearestClamp)
                .sampled(mirrored.depth, in.samplers->nearestClamp)
                .sampled(mirrored.normal, in.samplers->nearestClamp)
                .sampled(mirrored.reflector, in.samplers->nearestClamp)
                .sampled(gb.depth, in.samplers->nearestClamp);
            return pass;
        };
        gpu::PlanarResolvePush push{};
        push.planeGroup = v.planeGroup;
        push.reflectorCount = reflectors.count;
        resolvePass("planar.resolve." + plane, resolve_)
            .sampled(gb.reflector, in.samplers->nearestClamp)
            .hostStorage(reflectors.data)
            .storageReadWrite(reflection, &reflection)
            .storageReadWrite(out.path, &out.path)
            .sampled(mirrored.material, in.samplers->nearestClamp)
            .push(push)
            .dispatch(in.extent, gpu::kPlanarGroupSize);
        if (!glass || glass->used.height == 0 || !(*glass->planeGroups)[v.planeGroup]) continue;
        gpu::PlanarGlassPush glassPush{};
        glassPush.planeGroup = v.planeGroup;
        glassPush.regionCount = glass->regionCount;
        resolvePass("planar.glass." + plane, glassResolve_)
            .hostStorage(reflectors.data)
            .storageRead(glass->regions)
            .storageRead(glass->regionList)
            .storageReadWrite(out.glass, &out.glass)
            .push(glassPush)
            .dispatch(glass->used, gpu::kPlanarGroupSize);
    }
    return out;
}

}  // namespace ppr::passes
