#include "raytrace/raytrace_pass.hpp"

#include "common/clear_pass.hpp"
#include "common/reflected_path.hpp"
#include "raytrace/raytrace.h"
#include "raytrace_glass_comp.h"
#include "raytrace_reflect_comp.h"

#include <string>

namespace ppr::passes {
namespace {

// Bindings 0..10 (raytrace_common.glsl), checked against the shaders' reflected layout at push.
shader::PushDescriptors& commonWrites(shader::PushDescriptors& w, const FrameInputs& in, const RaytraceInputs& rt,
                                      const graph::PassContext& pc, graph::ImageHandle depth, graph::ImageHandle shadowMap) {
    const gpu::GpuScene& scene = *in.scene;
    return w.uniformBuffer(in.frameConstants, in.frameConstantsOffset, in.frameConstantsSize)
        .sampled(pc.view(depth), pc.layout(depth), in.samplers->nearestClamp)
        .sampled(pc.view(shadowMap), pc.layout(shadowMap), in.samplers->shadowCompare)
        .storageBuffer(rt.reflectors)
        .storageBuffer(in.drawReflectors)
        .storageBuffer(in.looseReflectors)
        .storageBuffer(scene.vertexBuffer())
        .storageBuffer(scene.indexBuffer())
        .storageBuffer(in.draws)
        .storageBuffer(scene.materialBuffer())
        .accelerationStructure(rt.tlas);
}

void bindTextures(VkCommandBuffer cmd, const shader::Pipeline& pipeline, const gpu::GpuScene& scene) {
    VkDescriptorSet textures = scene.textureSet();
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline.layout(), 1, 1, &textures, 0, nullptr);
}

}  // namespace

RaytracePass::RaytracePass(const vk::Context& ctx, const gpu::GpuScene& scene) : ctx_(ctx) {
    shader::PipelineLayoutDesc layout;
    layout.pushConstantBytes = sizeof(gpu::RaytracePush);
    layout.extraSets = {scene.textureSetLayout()};
    for (uint32_t raster = 0; raster < 2; ++raster) {
        const uint32_t specialization[] = {raster};  // kRasterCoverage
        const std::string suffix = raster ? ".raster" : "";
        screen_[raster] =
            shader::createComputePipeline(ctx, PPR_SPIRV(raytrace_reflect_comp), layout, "raytraced.reflect" + suffix, specialization);
        glass_[raster] = shader::createComputePipeline(ctx, PPR_SPIRV(raytrace_glass_comp), layout, "raytraced.glass" + suffix, specialization);
    }
}

graph::ImageHandle RaytracePass::addScreen(graph::RenderGraph& g, const FrameInputs& in, const RaytraceInputs& rt, const GBuffer& gb,
                                           bool normalMapped, graph::ImageHandle* distanceOut) const {
    struct Data {
        graph::ImageHandle depth, shadowMap, normal, reflector, out, distance;
    };
    const graph::ImageHandle target = g.createImage("raytraced.reflection", {in.extent.width, in.extent.height, kReflectionFormat, 1});
    // Path lengths only when asked for (TAA); otherwise a 1×1 stand-in the shader never writes.
    const VkExtent2D distanceSize = distanceOut ? in.extent : VkExtent2D{1, 1};
    const graph::ImageHandle distance =
        g.createImage(distanceOut ? "raytraced.distance" : "raytraced.distance.unused", {distanceSize.width, distanceSize.height, kReflectedPathFormat, 1});
    gpu::RaytracePush push{};
    push.flags = (normalMapped ? gpu::kRaytraceNormalMapped : 0u) | (distanceOut ? gpu::kRaytraceWriteDistance : 0u);
    push.looseCount = in.looseCount;
    push.subpixelBits = ctx_.info().subPixelPrecisionBits;
    const Data& d = g.addPass<Data>(
        "raytraced.reflect", graph::QueueKind::Compute,
        [&](graph::PassBuilder& b, Data& data) {
            data.depth = b.sampled(rt.depth);
            data.shadowMap = b.sampled(rt.shadowMap);
            data.normal = b.sampled(gb.normal);
            data.reflector = b.sampled(gb.reflector);
            data.out = b.storageWrite(target);  // every pixel written
            data.distance = b.storageWrite(distance);  // every pixel, when written at all
            if (rt.tlasBuilt) b.accelerationStructureRead(*rt.tlasBuilt);
        },
        [this, in, rt, push](const Data& data, graph::PassContext& pc) {
            const shader::Pipeline& pipeline = screen_[rt.rasterCoverage ? 1 : 0];
            VkCommandBuffer cmd = pc.cmd();
            pipeline.bind(cmd);
            shader::PushDescriptors w(ctx_);
            commonWrites(w, in, rt, pc, data.depth, data.shadowMap)
                .sampled(pc.view(data.normal), pc.layout(data.normal), in.samplers->nearestClamp)
                .sampled(pc.view(data.reflector), pc.layout(data.reflector), in.samplers->nearestClamp)
                .storageImage(pc.view(data.out))
                .storageImage(pc.view(data.distance))
                .push(cmd, pipeline);
            bindTextures(cmd, pipeline, *in.scene);
            pipeline.pushConstants(cmd, push);
            shader::dispatchCovering(cmd, in.extent, gpu::kRaytraceGroupSize);
        });
    if (distanceOut) *distanceOut = d.distance;
    return d.out;
}

graph::ImageHandle RaytracePass::addGlass(graph::RenderGraph& g, const FrameInputs& in, const RaytraceInputs& rt, const RaytraceGlass& glass) const {
    const uint32_t size = glass.atlasSize;
    graph::ImageHandle atlas = addClearPass(g, in, "raytraced.glass.clear", g.createImage("raytraced.glass", {size, size, kReflectionFormat, 1}), {});
    if (glass.used.height == 0 || glass.regionCount == 0) return atlas;
    struct Data {
        graph::ImageHandle depth, shadowMap, out;
        graph::BufferHandle regions, regionList;
    };
    gpu::RaytracePush push{};
    push.looseCount = in.looseCount;
    push.regionCount = glass.regionCount;
    push.subpixelBits = ctx_.info().subPixelPrecisionBits;
    const Data& d = g.addPass<Data>(
        "raytraced.glass", graph::QueueKind::Compute,
        [&](graph::PassBuilder& b, Data& data) {
            data.depth = b.sampled(rt.depth);
            data.shadowMap = b.sampled(rt.shadowMap);
            data.regions = b.storageRead(glass.regions);
            data.regionList = b.storageRead(glass.regionList);
            data.out = b.storageReadWrite(atlas);  // texels outside the panes keep the clear value
            if (rt.tlasBuilt) b.accelerationStructureRead(*rt.tlasBuilt);
        },
        [this, in, rt, push, dispatch = glass.used](const Data& data, graph::PassContext& pc) {
            const shader::Pipeline& pipeline = glass_[rt.rasterCoverage ? 1 : 0];
            VkCommandBuffer cmd = pc.cmd();
            pipeline.bind(cmd);
            shader::PushDescriptors w(ctx_);
            commonWrites(w, in, rt, pc, data.depth, data.shadowMap)
                .storageBuffer(pc.buffer(data.regions))
                .storageBuffer(pc.buffer(data.regionList))
                .storageImage(pc.view(data.out))
                .push(cmd, pipeline);
            bindTextures(cmd, pipeline, *in.scene);
            pipeline.pushConstants(cmd, push);
            shader::dispatchCovering(cmd, dispatch, gpu::kRaytraceGroupSize);
        });
    return d.out;
}

graph::BufferHandle RaytracePass::addTlasRebuild(graph::RenderGraph& g, gpu::SceneAccelerationStructures& structures, const gpu::GpuScene& scene,
                                                 uint32_t slot) {
    structures.prepareRebuild(slot, scene);
    tlasStorage_.buffer = structures.tlasStorage();
    tlasStorage_.desc = {structures.tlasStorageBytes()};
    scratch_.buffer = structures.scratchBuffer();
    scratch_.desc = {structures.scratchBytes()};
    struct Data {
        graph::BufferHandle tlas;
    };
    const graph::BufferHandle tlas = g.importBuffer("raytraced.tlas.storage", &tlasStorage_);
    const graph::BufferHandle scratch = g.importBuffer("raytraced.tlas.scratch", &scratch_);
    const gpu::SceneAccelerationStructures* built = &structures;
    const Data& d = g.addPass<Data>(
        "raytraced.tlas", graph::QueueKind::Compute,
        [&](graph::PassBuilder& b, Data& data) {
            data.tlas = b.accelerationStructureBuild(tlas);
            b.accelerationStructureBuild(scratch);
        },
        [built, slot](const Data&, graph::PassContext& pc) { built->recordRebuild(pc.cmd(), slot); });
    return d.tlas;
}

}  // namespace ppr::passes
