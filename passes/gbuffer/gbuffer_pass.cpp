#include "gbuffer/gbuffer_pass.hpp"

#include "gbuffer_frag.h"
#include "gbuffer_no_emissive_frag.h"
#include "gbuffer_vert.h"
#include "gpu/scene_data.h"

#include <stdexcept>
#include <vector>

namespace ppr::passes {

GBufferPass::GBufferPass(const vk::Context& ctx, const gpu::GpuScene& scene) : ctx_(ctx), emissive_(scene.cpu().opaqueMaterialEmits()) {
    // Not a format Vulkan requires as a colour attachment, though every desktop driver and lavapipe render to it.
    VkFormatProperties emissive{};
    vkGetPhysicalDeviceFormatProperties(ctx.physicalDevice(), kEmissiveFormat, &emissive);
    constexpr VkFormatFeatureFlags kNeeded = VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BIT | VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT;
    if (emissive_ && (emissive.optimalTilingFeatures & kNeeded) != kNeeded)
        throw std::runtime_error("device: cannot render to VK_FORMAT_B10G11R11_UFLOAT_PACK32 (the G-buffer's emissive target)");
    std::vector<VkFormat> targets = {kNormalFormat, kAlbedoFormat, kMaterialFormat, kReflectorFormat};
    if (emissive_) targets.push_back(kEmissiveFormat);
    shader::PipelineLayoutDesc layout;
    layout.stages = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;
    layout.pushConstantBytes = sizeof(gpu::DrawPush);
    layout.extraSets = {scene.textureSetLayout()};
    pipeline_ = shader::GraphicsPipelineBuilder(ctx, "gbuffer")
                    .vertex(PPR_SPIRV(gbuffer_vert))
                    .fragment(emissive_ ? PPR_SPIRV(gbuffer_frag) : PPR_SPIRV(gbuffer_no_emissive_frag))
                    .layout(layout)
                    .vertexInput(sizeof(scene::Vertex), sceneVertexAttributes(false))
                    .colorFormats(targets)
                    .depth(kDepthFormat, true, true, VK_COMPARE_OP_GREATER)
                    .build();
    // The pre-pass leaves each pixel's nearest depth pushed slightly farther (reverse-Z: smaller), and
    // the shading pass then runs exactly as without it, from that depth instead of from 0: the nearest
    // fragment, or the first drawn of several at one depth, still passes and writes, and only it (and
    // whatever lies within the bias behind it) is shaded. So the images are the same bit for bit, ties
    // included (an equal test would let the last of them win). The bias covers the two pipelines'
    // depths differing in rounding: on lavapipe 4 steps alone left one pixel unshaded on the stairs in
    // one of TAA's 16 jitter phases (gpu.DepthPrepass.*). Masked draws are left out: their alpha test
    // decides their depth.
    shader::PipelineLayoutDesc depthLayout;
    depthLayout.stages = VK_SHADER_STAGE_VERTEX_BIT;
    depthLayout.pushConstantBytes = sizeof(gpu::DrawPush);
    prepassPipeline_ = shader::GraphicsPipelineBuilder(ctx, "gbuffer.prepass")
                           .vertex(PPR_SPIRV(gbuffer_vert))
                           .layout(depthLayout)
                           .vertexInput(sizeof(scene::Vertex), sceneVertexAttributes(false))
                           .depth(kDepthFormat, true, true, VK_COMPARE_OP_GREATER)
                           .depthBias(-kPrepassBiasSteps, -kPrepassBiasSlope)
                           .build();
}

GBuffer GBufferPass::createTargets(graph::RenderGraph& g, const std::string& name, VkExtent2D extent) const {
    const uint32_t w = extent.width, h = extent.height;
    GBuffer out;
    out.depth = g.createImage(name + ".depth", {w, h, kDepthFormat, 1});
    out.normal = g.createImage(name + ".normal", {w, h, kNormalFormat, 1});
    out.albedo = g.createImage(name + ".albedo", {w, h, kAlbedoFormat, 1});
    out.material = g.createImage(name + ".material", {w, h, kMaterialFormat, 1});
    out.reflector = g.createImage(name + ".reflector", {w, h, kReflectorFormat, 1});
    if (emissive_) out.emissive = g.createImage(name + ".emissive", {w, h, kEmissiveFormat, 1});
    return out;
}

GBuffer GBufferPass::add(graph::RenderGraph& g, const FrameInputs& in, const std::string& name, const GBuffer* targets) const {
    GBuffer out = targets ? *targets : createTargets(g, name, in.extent);
    if (in.depthPrepass) out.depth = addPrepass(g, in, name + ".prepass", out.depth);
    const GBuffer& d = g.addPass<GBuffer>(
        name, graph::QueueKind::Graphics,
        [&](graph::PassBuilder& b, GBuffer& data) {
            data.normal = b.colorAttachment(out.normal, graph::LoadOp::Clear, {{0.0f, 0.0f, 0.0f, 0.0f}});
            data.albedo = b.colorAttachment(out.albedo, graph::LoadOp::Clear, {{0.0f, 0.0f, 0.0f, 0.0f}});
            data.material = b.colorAttachment(out.material, graph::LoadOp::Clear, {{1.0f, 0.0f, 0.0f, 0.0f}});
            VkClearColorValue zero{};
            data.reflector = b.colorAttachment(out.reflector, graph::LoadOp::Clear, zero);
            if (out.emissive.valid()) data.emissive = b.colorAttachment(out.emissive, graph::LoadOp::Clear, {{0.0f, 0.0f, 0.0f, 0.0f}});
            data.depth = b.depthAttachment(out.depth, in.depthPrepass ? graph::LoadOp::Load : graph::LoadOp::Clear, 0.0f);
        },
        [this, in](const GBuffer&, graph::PassContext& pc) {
            VkCommandBuffer cmd = pc.cmd();
            pipeline_.bind(cmd);
            shader::PushDescriptors(ctx_)
                .uniformBuffer(in.frameConstants, in.frameConstantsOffset, in.frameConstantsSize)
                .storageBuffer(in.draws)
                .storageBuffer(in.scene->materialBuffer())
                .storageBuffer(in.drawReflectors)
                .storageBuffer(in.reflectors)
                .storageBuffer(in.looseReflectors)
                .push(cmd, pipeline_);
            VkDescriptorSet textures = in.scene->textureSet();
            vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_.layout(), 1, 1, &textures, 0, nullptr);
            in.scene->drawOpaque(cmd, [&](uint32_t i) { pipeline_.pushConstants(cmd, gpu::DrawPush{i, in.looseCount, 0, 0}); });
        });
    return d;
}

graph::ImageHandle GBufferPass::addPrepass(graph::RenderGraph& g, const FrameInputs& in, const std::string& name, graph::ImageHandle depth) const {
    struct Data {
        graph::ImageHandle depth;
    };
    const Data& d = g.addPass<Data>(
        name, graph::QueueKind::Graphics,
        [&](graph::PassBuilder& b, Data& data) { data.depth = b.depthAttachment(depth, graph::LoadOp::Clear, 0.0f); },
        [this, in](const Data&, graph::PassContext& pc) { drawUnmaskedDepth(ctx_, pc.cmd(), prepassPipeline_, in); });
    return d.depth;
}

}  // namespace ppr::passes
