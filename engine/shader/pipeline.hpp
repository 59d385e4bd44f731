#pragma once
// Pipelines from embedded SPIR-V (compiled at build time, see cmake/Shaders.cmake). Resources of a
// pass are bound with push descriptors (set 0), so no descriptor set is allocated per frame. Set 0's
// layout is read from the SPIR-V (spirv_reflect.hpp): the GLSL is the only place a pass declares it.
#include "vk/context.hpp"

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace ppr::shader {

struct Spirv {
    const uint32_t* code;
    size_t bytes;
};
#define PPR_SPIRV(var) ::ppr::shader::Spirv{var, sizeof(var)}

// What the SPIR-V does not say. Set 0 (push descriptors, visible to `stages`) comes from reflection;
// a push-constant block in the shaders must be exactly `pushConstantBytes` (the shared header's sizeof).
struct PipelineLayoutDesc {
    VkShaderStageFlags stages = VK_SHADER_STAGE_COMPUTE_BIT;
    uint32_t pushConstantBytes = 0;
    std::vector<VkDescriptorSetLayout> extraSets;  // sets 1.. (e.g. the scene's bindless textures)
};

class Pipeline {
public:
    Pipeline() = default;
    ~Pipeline();
    Pipeline(Pipeline&&) noexcept;
    Pipeline& operator=(Pipeline&&) noexcept;
    Pipeline(const Pipeline&) = delete;
    Pipeline& operator=(const Pipeline&) = delete;

    VkPipeline handle() const { return pipeline_; }
    VkPipelineLayout layout() const { return layout_; }
    VkPipelineBindPoint bindPoint() const { return bindPoint_; }
    uint32_t pushConstantBytes() const { return pushBytes_; }
    VkShaderStageFlags stages() const { return stages_; }
    const std::string& name() const { return name_; }
    // Set 0's descriptor types in binding order (from the shaders), which binding calls must match.
    std::span<const VkDescriptorType> bindingTypes() const { return bindings_; }

    void bind(VkCommandBuffer cmd) const { vkCmdBindPipeline(cmd, bindPoint_, pipeline_); }
    void pushConstants(VkCommandBuffer cmd, const void* data, uint32_t bytes) const;
    template <class T>
    void pushConstants(VkCommandBuffer cmd, const T& data) const { pushConstants(cmd, &data, sizeof(T)); }

private:
    friend Pipeline createComputePipeline(const vk::Context&, Spirv, const PipelineLayoutDesc&, const std::string&,
                                          std::span<const uint32_t>);
    friend class GraphicsPipelineBuilder;
    void reset();
    VkDevice device_ = VK_NULL_HANDLE;
    VkPipeline pipeline_ = VK_NULL_HANDLE;
    VkPipelineLayout layout_ = VK_NULL_HANDLE;
    VkDescriptorSetLayout pushSetLayout_ = VK_NULL_HANDLE;
    VkPipelineBindPoint bindPoint_ = VK_PIPELINE_BIND_POINT_COMPUTE;
    uint32_t pushBytes_ = 0;
    VkShaderStageFlags stages_ = 0;
    std::string name_;
    std::vector<VkDescriptorType> bindings_;
};

// `specialization[i]` is the value of the shader's `constant_id = i` (uint constants, e.g. a workgroup size).
Pipeline createComputePipeline(const vk::Context& ctx, Spirv spirv, const PipelineLayoutDesc& layout, const std::string& name,
                               std::span<const uint32_t> specialization = {});

class GraphicsPipelineBuilder {
public:
    GraphicsPipelineBuilder(const vk::Context& ctx, std::string name) : ctx_(ctx), name_(std::move(name)) {}
    GraphicsPipelineBuilder& vertex(Spirv s) { vert_ = s; return *this; }
    GraphicsPipelineBuilder& fragment(Spirv s) { frag_ = s; hasFrag_ = true; return *this; }
    GraphicsPipelineBuilder& layout(const PipelineLayoutDesc& l) { layout_ = l; return *this; }
    GraphicsPipelineBuilder& vertexInput(uint32_t stride, std::vector<VkVertexInputAttributeDescription> attrs);
    GraphicsPipelineBuilder& colorFormats(std::vector<VkFormat> f) { colorFormats_ = std::move(f); return *this; }
    GraphicsPipelineBuilder& depth(VkFormat f, bool test, bool write, VkCompareOp op);
    GraphicsPipelineBuilder& cull(VkCullModeFlags mode) { cull_ = mode; return *this; }
    GraphicsPipelineBuilder& depthBias(float constant, float slope) { biasConst_ = constant; biasSlope_ = slope; return *this; }
    GraphicsPipelineBuilder& depthClamp(bool on) { depthClamp_ = on; return *this; }
    // Colour attachment 0 becomes src0 + dst × src1 (dual-source blending): a transparent surface
    // adds what it reflects and filters what it lets through, per channel.
    GraphicsPipelineBuilder& addAndFilterBlend() { addAndFilter_ = true; return *this; }
    Pipeline build();

private:
    const vk::Context& ctx_;
    std::string name_;
    Spirv vert_{};
    Spirv frag_{};
    bool hasFrag_ = false;
    PipelineLayoutDesc layout_;
    uint32_t stride_ = 0;
    std::vector<VkVertexInputAttributeDescription> attrs_;
    std::vector<VkFormat> colorFormats_;
    VkFormat depthFormat_ = VK_FORMAT_UNDEFINED;
    bool depthTest_ = false, depthWrite_ = false;
    VkCompareOp depthOp_ = VK_COMPARE_OP_ALWAYS;
    VkCullModeFlags cull_ = VK_CULL_MODE_NONE;
    float biasConst_ = 0.0f, biasSlope_ = 0.0f;
    bool depthClamp_ = false;
    bool addAndFilter_ = false;
};

// Collects descriptor writes for set 0 and pushes them with vkCmdPushDescriptorSetKHR.
// Bindings are numbered in call order; push() throws std::logic_error unless their number and types
// match the pipeline's set 0 (Pipeline::bindingTypes).
class PushDescriptors {
public:
    explicit PushDescriptors(const vk::Context& ctx);
    PushDescriptors& sampled(VkImageView view, VkImageLayout layout, VkSampler sampler);
    PushDescriptors& storageImage(VkImageView view);
    PushDescriptors& storageBuffer(VkBuffer buffer, VkDeviceSize offset = 0, VkDeviceSize range = VK_WHOLE_SIZE);
    PushDescriptors& uniformBuffer(VkBuffer buffer, VkDeviceSize offset, VkDeviceSize range);
    PushDescriptors& accelerationStructure(VkAccelerationStructureKHR tlas);  // ray queries
    void push(VkCommandBuffer cmd, const Pipeline& pipeline);

private:
    static constexpr uint32_t kMax = 32;  // VK_KHR_push_descriptor guarantees maxPushDescriptors >= 32
    PFN_vkCmdPushDescriptorSetKHR fn_;
    VkWriteDescriptorSet writes_[kMax]{};
    VkDescriptorImageInfo images_[kMax]{};
    VkDescriptorBufferInfo buffers_[kMax]{};
    VkAccelerationStructureKHR structures_[kMax]{};
    VkWriteDescriptorSetAccelerationStructureKHR structureWrites_[kMax]{};
    uint32_t count_ = 0;
    VkWriteDescriptorSet& next(VkDescriptorType type);
};

// vkCmdDispatch with enough square workgroups of `groupSize`² threads to cover `extent`.
inline void dispatchCovering(VkCommandBuffer cmd, VkExtent2D extent, uint32_t groupSize) {
    vkCmdDispatch(cmd, (extent.width + groupSize - 1) / groupSize, (extent.height + groupSize - 1) / groupSize, 1);
}

// Common samplers, created once per run.
struct Samplers {
    VkSampler linearClamp = VK_NULL_HANDLE;
    VkSampler nearestClamp = VK_NULL_HANDLE;
    VkSampler linearRepeatAniso = VK_NULL_HANDLE;  // material textures (mipmapped)
    VkSampler shadowCompare = VK_NULL_HANDLE;      // reverse-Z depth comparison (GREATER_OR_EQUAL)
    void create(const vk::Context& ctx);
    void destroy(const vk::Context& ctx);
};

}  // namespace ppr::shader
