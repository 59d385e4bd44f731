#include "raytrace/raytrace_pass.hpp"

#include "common/clear_pass.hpp"
#include "raytrace/raytrace.h"
#include "raytrace_glass_comp.h"
#include "raytrace_reflect_comp.h"
#include "shader/layout_check.hpp"

#include <array>
#include <stdexcept>

namespace ppr::passes {
namespace {

constexpr VkDescriptorType kUniform = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
constexpr VkDescriptorType kSampled = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
constexpr VkDescriptorType kStorage = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
constexpr VkDescriptorType kImage = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
constexpr VkDescriptorType kTlas = VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR;

// Set 0 bindings 0..10, shared by both shaders (raytrace_common.glsl).
std::vector<VkDescriptorType> commonBindings() {
    return {kUniform, kSampled, kSampled, kStorage, kStorage, kStorage, kStorage, kStorage, kStorage, kStorage, kTlas};
}

// Push-descriptor writes for set 0, acceleration structures included (shader::PushDescriptors has
// no such binding kind); bindings numbered in call order.
class Writes {
public:
    explicit Writes(const vk::Context& ctx) : ctx_(ctx) {}
    Writes& uniform(VkBuffer buffer, VkDeviceSize offset, VkDeviceSize range) { return bufferWrite(kUniform, buffer, offset, range); }
    Writes& storage(VkBuffer buffer) { return bufferWrite(kStorage, buffer, 0, VK_WHOLE_SIZE); }
    Writes& sampled(VkImageView view, VkImageLayout layout, VkSampler sampler) { return imageWrite(kSampled, view, layout, sampler); }
    Writes& image(VkImageView view, VkImageLayout layout) { return imageWrite(kImage, view, layout, VK_NULL_HANDLE); }
    Writes& tlas(VkAccelerationStructureKHR tlas) {
        tlas_ = tlas;
        tlasWrite_ = {VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET_ACCELERATION_STRUCTURE_KHR};
        tlasWrite_.accelerationStructureCount = 1;
        tlasWrite_.pAccelerationStructures = &tlas_;
        next(kTlas).pNext = &tlasWrite_;
        return *this;
    }
    void push(VkCommandBuffer cmd, const shader::Pipeline& pipeline) const {
        std::array<VkDescriptorType, 16> given{};
        for (uint32_t i = 0; i < count_; ++i) given[i] = writes_[i].descriptorType;
        shader::checkBindings(pipeline.name(), {}, pipeline.bindingTypes(), {given.data(), count_});
        ctx_.pushDescriptorSet()(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline.layout(), 0, count_, writes_.data());
    }

private:
    Writes& bufferWrite(VkDescriptorType type, VkBuffer buffer, VkDeviceSize offset, VkDeviceSize range) {
        VkWriteDescriptorSet& w = next(type);
        buffers_[w.dstBinding] = {buffer, offset, range};
        w.pBufferInfo = &buffers_[w.dstBinding];
        return *this;
    }
    Writes& imageWrite(VkDescriptorType type, VkImageView view, VkImageLayout layout, VkSampler sampler) {
        VkWriteDescriptorSet& w = next(type);
        images_[w.dstBinding] = {sampler, view, layout};
        w.pImageInfo = &images_[w.dstBinding];
        return *this;
    }
    VkWriteDescriptorSet& next(VkDescriptorType type) {
        if (count_ == writes_.size()) throw std::logic_error("raytrace: too many descriptor writes");
        VkWriteDescriptorSet& w = writes_[count_];
        w = {VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
        w.dstBinding = count_++;
        w.descriptorCount = 1;
        w.descriptorType = type;
        return w;
    }
    const vk::Context& ctx_;
    std::array<VkWriteDescriptorSet, 16> writes_{};
    std::array<VkDescriptorImageInfo, 16> images_{};
    std::array<VkDescriptorBufferInfo, 16> buffers_{};
    VkAccelerationStructureKHR tlas_ = VK_NULL_HANDLE;
    VkWriteDescriptorSetAccelerationStructureKHR tlasWrite_{};
    uint32_t count_ = 0;
};

// Bindings 0..10 (raytrace_common.glsl) and the material textures (set 1).
Writes& commonWrites(Writes& w, const FrameInputs& in, const RaytraceInputs& rt, const graph::PassContext& pc, graph::ImageHandle depth,
                     graph::ImageHandle shadowMap) {
    const gpu::GpuScene& scene = *in.scene;
    return w.uniform(in.frameConstants, in.frameConstantsOffset, in.frameConstantsSize)
        .sampled(pc.view(depth), pc.layout(depth), in.samplers->nearestClamp)
        .sampled(pc.view(shadowMap), pc.layout(shadowMap), in.samplers->shadowCompare)
        .storage(rt.reflectors)
        .storage(in.drawReflectors)
        .storage(in.looseReflectors)
        .storage(scene.vertexBuffer())
        .storage(scene.indexBuffer())
        .storage(scene.drawBuffer())
        .storage(scene.materialBuffer())
        .tlas(rt.tlas);
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
    screen_ = shader::createComputePipeline(ctx, PPR_SPIRV(raytrace_reflect_comp), layout, "raytraced.reflect");
    glass_ = shader::createComputePipeline(ctx, PPR_SPIRV(raytrace_glass_comp), layout, "raytraced.glass");
    // What the passes below write, in binding order, against the shaders' set 0 (fails at start-up).
    std::vector<VkDescriptorType> screen = commonBindings(), glass = commonBindings();
    screen.insert(screen.end(), {kSampled, kSampled, kImage});
    glass.insert(glass.end(), {kStorage, kStorage, kImage});
    shader::checkBindings(screen_.name(), "raytraced.reflect", screen_.bindingTypes(), screen);
    shader::checkBindings(glass_.name(), "raytraced.glass", glass_.bindingTypes(), glass);
}

graph::ImageHandle RaytracePass::addScreen(graph::RenderGraph& g, const FrameInputs& in, const RaytraceInputs& rt, const GBuffer& gb,
                                           bool normalMapped) const {
    struct Data {
        graph::ImageHandle depth, shadowMap, normal, reflector, out;
    };
    const graph::ImageHandle target = g.createImage("raytraced.reflection", {in.extent.width, in.extent.height, kReflectionFormat, 1});
    gpu::RaytracePush push{};
    push.flags = normalMapped ? gpu::kRaytraceNormalMapped : 0u;
    push.looseCount = in.looseCount;
    const Data& d = g.addPass<Data>(
        "raytraced.reflect", graph::QueueKind::Compute,
        [&](graph::PassBuilder& b, Data& data) {
            data.depth = b.sampled(rt.depth);
            data.shadowMap = b.sampled(rt.shadowMap);
            data.normal = b.sampled(gb.normal);
            data.reflector = b.sampled(gb.reflector);
            data.out = b.storageWrite(target);  // every pixel written
        },
        [this, in, rt, push](const Data& data, graph::PassContext& pc) {
            VkCommandBuffer cmd = pc.cmd();
            screen_.bind(cmd);
            Writes w(ctx_);
            commonWrites(w, in, rt, pc, data.depth, data.shadowMap)
                .sampled(pc.view(data.normal), pc.layout(data.normal), in.samplers->nearestClamp)
                .sampled(pc.view(data.reflector), pc.layout(data.reflector), in.samplers->nearestClamp)
                .image(pc.view(data.out), pc.layout(data.out))
                .push(cmd, screen_);
            bindTextures(cmd, screen_, *in.scene);
            screen_.pushConstants(cmd, push);
            shader::dispatchCovering(cmd, in.extent, gpu::kRaytraceGroupSize);
        });
    return d.out;
}

graph::ImageHandle RaytracePass::addGlass(graph::RenderGraph& g, const FrameInputs& in, const RaytraceInputs& rt, const RaytraceGlass& glass) const {
    const uint32_t size = glass.atlasSize;
    graph::ImageHandle atlas = addClearPass(g, "raytraced.glass.clear", g.createImage("raytraced.glass", {size, size, kReflectionFormat, 1}), {});
    if (glass.usedHeight == 0 || glass.regionCount == 0) return atlas;
    struct Data {
        graph::ImageHandle depth, shadowMap, out;
        graph::BufferHandle regions, regionList;
    };
    gpu::RaytracePush push{};
    push.looseCount = in.looseCount;
    push.regionCount = glass.regionCount;
    const VkExtent2D dispatch{size, glass.usedHeight};  // only the atlas rows holding regions
    const Data& d = g.addPass<Data>(
        "raytraced.glass", graph::QueueKind::Compute,
        [&](graph::PassBuilder& b, Data& data) {
            data.depth = b.sampled(rt.depth);
            data.shadowMap = b.sampled(rt.shadowMap);
            data.regions = b.storageRead(glass.regions);
            data.regionList = b.storageRead(glass.regionList);
            data.out = b.storageReadWrite(atlas);  // texels outside the panes keep the clear value
        },
        [this, in, rt, push, dispatch](const Data& data, graph::PassContext& pc) {
            VkCommandBuffer cmd = pc.cmd();
            glass_.bind(cmd);
            Writes w(ctx_);
            commonWrites(w, in, rt, pc, data.depth, data.shadowMap)
                .storage(pc.buffer(data.regions))
                .storage(pc.buffer(data.regionList))
                .image(pc.view(data.out), pc.layout(data.out))
                .push(cmd, glass_);
            bindTextures(cmd, glass_, *in.scene);
            glass_.pushConstants(cmd, push);
            shader::dispatchCovering(cmd, dispatch, gpu::kRaytraceGroupSize);
        });
    return d.out;
}

}  // namespace ppr::passes
