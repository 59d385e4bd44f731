#include "shader/pipeline.hpp"

#include "shader/layout_check.hpp"
#include "shader/spirv_reflect.hpp"
#include "vk/live_objects.hpp"

#include <stdexcept>
#include <utility>

namespace ppr::shader {
namespace {

VkShaderModule createModule(const vk::Context& ctx, Spirv s, const std::string& name) {
    VkShaderModuleCreateInfo ci{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
    ci.codeSize = s.bytes;
    ci.pCode = s.code;
    VkShaderModule m;
    VK_CHECK(vkCreateShaderModule(ctx.device(), &ci, nullptr, &m));
    ctx.name(m, VK_OBJECT_TYPE_SHADER_MODULE, name);
    return m;
}

ReflectedLayout reflect(Spirv s, const std::string& what) {
    if (s.bytes % sizeof(uint32_t) != 0) throw std::runtime_error("SPIR-V of " + what + " is not a whole number of words");
    return reflectSpirv({s.code, s.bytes / sizeof(uint32_t)}, what);
}

void createLayout(const vk::Context& ctx, const PipelineLayoutDesc& desc, std::span<const VkDescriptorType> set0, const std::string& name,
                  VkDescriptorSetLayout& setLayout, VkPipelineLayout& layout) {
    std::vector<VkDescriptorSetLayoutBinding> bindings;
    for (uint32_t i = 0; i < set0.size(); ++i) bindings.push_back({i, set0[i], 1, desc.stages, nullptr});
    VkDescriptorSetLayoutCreateInfo sci{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    sci.flags = VK_DESCRIPTOR_SET_LAYOUT_CREATE_PUSH_DESCRIPTOR_BIT_KHR;
    sci.bindingCount = static_cast<uint32_t>(bindings.size());
    sci.pBindings = bindings.data();
    VK_CHECK(vkCreateDescriptorSetLayout(ctx.device(), &sci, nullptr, &setLayout));
    ++vk::liveObjects().descriptorSetLayouts;
    ctx.name(setLayout, VK_OBJECT_TYPE_DESCRIPTOR_SET_LAYOUT, name + " set0");

    std::vector<VkDescriptorSetLayout> sets{setLayout};
    sets.insert(sets.end(), desc.extraSets.begin(), desc.extraSets.end());
    VkPushConstantRange range{desc.stages, 0, desc.pushConstantBytes};
    VkPipelineLayoutCreateInfo lci{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    lci.setLayoutCount = static_cast<uint32_t>(sets.size());
    lci.pSetLayouts = sets.data();
    lci.pushConstantRangeCount = desc.pushConstantBytes ? 1 : 0;
    lci.pPushConstantRanges = &range;
    VK_CHECK(vkCreatePipelineLayout(ctx.device(), &lci, nullptr, &layout));
    ctx.name(layout, VK_OBJECT_TYPE_PIPELINE_LAYOUT, name);
}

}  // namespace

Pipeline::~Pipeline() { reset(); }

Pipeline::Pipeline(Pipeline&& o) noexcept { *this = std::move(o); }

Pipeline& Pipeline::operator=(Pipeline&& o) noexcept {
    if (this != &o) {
        reset();
        device_ = std::exchange(o.device_, VK_NULL_HANDLE);
        pipeline_ = std::exchange(o.pipeline_, VK_NULL_HANDLE);
        layout_ = std::exchange(o.layout_, VK_NULL_HANDLE);
        pushSetLayout_ = std::exchange(o.pushSetLayout_, VK_NULL_HANDLE);
        bindPoint_ = o.bindPoint_;
        pushBytes_ = o.pushBytes_;
        stages_ = o.stages_;
        name_ = std::move(o.name_);
        bindings_ = std::move(o.bindings_);
    }
    return *this;
}

void Pipeline::reset() {
    if (!device_) return;
    if (pipeline_) vkDestroyPipeline(device_, pipeline_, nullptr), --vk::liveObjects().pipelines;
    if (layout_) vkDestroyPipelineLayout(device_, layout_, nullptr);
    if (pushSetLayout_) vkDestroyDescriptorSetLayout(device_, pushSetLayout_, nullptr), --vk::liveObjects().descriptorSetLayouts;
    device_ = VK_NULL_HANDLE;
    pipeline_ = VK_NULL_HANDLE;
    layout_ = VK_NULL_HANDLE;
    pushSetLayout_ = VK_NULL_HANDLE;
}

void Pipeline::pushConstants(VkCommandBuffer cmd, const void* data, uint32_t bytes) const {
    if (bytes > pushBytes_) throw std::logic_error("pipeline '" + name_ + "': push constants larger than the pipeline layout declares");
    vkCmdPushConstants(cmd, layout_, stages_, 0, bytes, data);
}

Pipeline createComputePipeline(const vk::Context& ctx, Spirv spirv, const PipelineLayoutDesc& desc, const std::string& name,
                               std::span<const uint32_t> specialization) {
    Pipeline p;
    p.device_ = ctx.device();
    p.bindPoint_ = VK_PIPELINE_BIND_POINT_COMPUTE;
    PipelineLayoutDesc d = desc;
    d.stages = VK_SHADER_STAGE_COMPUTE_BIT;
    p.stages_ = d.stages;
    p.pushBytes_ = d.pushConstantBytes;
    p.name_ = name;
    p.bindings_ = pushSetTypes(reflect(spirv, name + ".comp"), d.pushConstantBytes, d.extraSets.size(), name);
    createLayout(ctx, d, p.bindings_, name, p.pushSetLayout_, p.layout_);
    VkShaderModule module = createModule(ctx, spirv, name);
    VkComputePipelineCreateInfo ci{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
    std::vector<VkSpecializationMapEntry> entries;
    for (uint32_t i = 0; i < specialization.size(); ++i) entries.push_back({i, i * uint32_t(sizeof(uint32_t)), sizeof(uint32_t)});
    const VkSpecializationInfo spec{uint32_t(entries.size()), entries.data(), specialization.size_bytes(), specialization.data()};
    ci.stage = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO, nullptr, 0, VK_SHADER_STAGE_COMPUTE_BIT, module, "main",
                specialization.empty() ? nullptr : &spec};
    ci.layout = p.layout_;
    VkResult r = vkCreateComputePipelines(ctx.device(), VK_NULL_HANDLE, 1, &ci, nullptr, &p.pipeline_);
    vkDestroyShaderModule(ctx.device(), module, nullptr);
    VK_CHECK(r);
    ++vk::liveObjects().pipelines;
    ctx.name(p.pipeline_, VK_OBJECT_TYPE_PIPELINE, name);
    return p;
}

GraphicsPipelineBuilder& GraphicsPipelineBuilder::vertexInput(uint32_t stride, std::vector<VkVertexInputAttributeDescription> attrs) {
    stride_ = stride;
    attrs_ = std::move(attrs);
    return *this;
}

GraphicsPipelineBuilder& GraphicsPipelineBuilder::depth(VkFormat f, bool test, bool write, VkCompareOp op) {
    depthFormat_ = f;
    depthTest_ = test;
    depthWrite_ = write;
    depthOp_ = op;
    return *this;
}

Pipeline GraphicsPipelineBuilder::build() {
    Pipeline p;
    p.device_ = ctx_.device();
    p.bindPoint_ = VK_PIPELINE_BIND_POINT_GRAPHICS;
    if (layout_.stages == VK_SHADER_STAGE_COMPUTE_BIT) layout_.stages = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;
    p.stages_ = layout_.stages;
    p.pushBytes_ = layout_.pushConstantBytes;
    ReflectedLayout reflected = reflect(vert_, name_ + ".vert");
    if (hasFrag_) mergeStage(reflected, reflect(frag_, name_ + ".frag"), "pipeline '" + name_ + "'");
    p.name_ = name_;
    p.bindings_ = pushSetTypes(reflected, layout_.pushConstantBytes, layout_.extraSets.size(), name_);
    createLayout(ctx_, layout_, p.bindings_, name_, p.pushSetLayout_, p.layout_);

    VkShaderModule vs = createModule(ctx_, vert_, name_ + ".vert");
    VkShaderModule fs = hasFrag_ ? createModule(ctx_, frag_, name_ + ".frag") : VK_NULL_HANDLE;
    VkPipelineShaderStageCreateInfo stages[2] = {
        {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO, nullptr, 0, VK_SHADER_STAGE_VERTEX_BIT, vs, "main", nullptr},
        {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO, nullptr, 0, VK_SHADER_STAGE_FRAGMENT_BIT, fs, "main", nullptr}};

    VkVertexInputBindingDescription binding{0, stride_, VK_VERTEX_INPUT_RATE_VERTEX};
    VkPipelineVertexInputStateCreateInfo vi{VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
    if (stride_) {
        vi.vertexBindingDescriptionCount = 1;
        vi.pVertexBindingDescriptions = &binding;
        vi.vertexAttributeDescriptionCount = static_cast<uint32_t>(attrs_.size());
        vi.pVertexAttributeDescriptions = attrs_.data();
    }
    VkPipelineInputAssemblyStateCreateInfo ia{VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
    ia.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
    VkPipelineViewportStateCreateInfo vp{VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO};
    vp.viewportCount = 1;
    vp.scissorCount = 1;
    VkPipelineRasterizationStateCreateInfo rs{VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
    rs.polygonMode = VK_POLYGON_MODE_FILL;
    rs.cullMode = cull_;
    rs.frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE;
    rs.lineWidth = 1.0f;
    rs.depthClampEnable = depthClamp_ ? VK_TRUE : VK_FALSE;
    if (biasConst_ != 0.0f || biasSlope_ != 0.0f) {
        rs.depthBiasEnable = VK_TRUE;
        rs.depthBiasConstantFactor = biasConst_;
        rs.depthBiasSlopeFactor = biasSlope_;
    }
    VkPipelineMultisampleStateCreateInfo ms{VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
    ms.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;
    VkPipelineDepthStencilStateCreateInfo ds{VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO};
    ds.depthTestEnable = depthTest_;
    ds.depthWriteEnable = depthWrite_;
    ds.depthCompareOp = depthOp_;
    std::vector<VkPipelineColorBlendAttachmentState> blends(colorFormats_.size());
    for (auto& b : blends) b.colorWriteMask = 0xF;
    if (addAndFilter_ && !blends.empty()) {
        VkPipelineColorBlendAttachmentState& b = blends[0];
        b.blendEnable = VK_TRUE;
        b.srcColorBlendFactor = VK_BLEND_FACTOR_ONE;
        b.dstColorBlendFactor = VK_BLEND_FACTOR_SRC1_COLOR;
        b.colorBlendOp = VK_BLEND_OP_ADD;
        b.srcAlphaBlendFactor = VK_BLEND_FACTOR_ZERO;  // keep the destination's alpha
        b.dstAlphaBlendFactor = VK_BLEND_FACTOR_ONE;
        b.alphaBlendOp = VK_BLEND_OP_ADD;
    }
    VkPipelineColorBlendStateCreateInfo cb{VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
    cb.attachmentCount = static_cast<uint32_t>(blends.size());
    cb.pAttachments = blends.data();
    VkDynamicState dyn[] = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR};
    VkPipelineDynamicStateCreateInfo dy{VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO};
    dy.dynamicStateCount = 2;
    dy.pDynamicStates = dyn;
    VkPipelineRenderingCreateInfo ri{VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO};
    ri.colorAttachmentCount = static_cast<uint32_t>(colorFormats_.size());
    ri.pColorAttachmentFormats = colorFormats_.data();
    ri.depthAttachmentFormat = depthFormat_;

    VkGraphicsPipelineCreateInfo ci{VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO};
    ci.pNext = &ri;
    ci.stageCount = hasFrag_ ? 2 : 1;
    ci.pStages = stages;
    ci.pVertexInputState = &vi;
    ci.pInputAssemblyState = &ia;
    ci.pViewportState = &vp;
    ci.pRasterizationState = &rs;
    ci.pMultisampleState = &ms;
    ci.pDepthStencilState = &ds;
    ci.pColorBlendState = &cb;
    ci.pDynamicState = &dy;
    ci.layout = p.layout_;
    VkResult r = vkCreateGraphicsPipelines(ctx_.device(), VK_NULL_HANDLE, 1, &ci, nullptr, &p.pipeline_);
    vkDestroyShaderModule(ctx_.device(), vs, nullptr);
    if (fs) vkDestroyShaderModule(ctx_.device(), fs, nullptr);
    VK_CHECK(r);
    ++vk::liveObjects().pipelines;
    ctx_.name(p.pipeline_, VK_OBJECT_TYPE_PIPELINE, name_);
    return p;
}

PushDescriptors::PushDescriptors(const vk::Context& ctx) {
    fn_ = ctx.pushDescriptorSet();
    if (!fn_) throw std::runtime_error("vulkan: vkCmdPushDescriptorSetKHR unavailable");
}

VkWriteDescriptorSet& PushDescriptors::next(VkDescriptorType type) {
    if (count_ >= kMax) throw std::logic_error("PushDescriptors: too many bindings");
    VkWriteDescriptorSet& w = writes_[count_];
    w = {VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    w.dstBinding = count_;
    w.descriptorCount = 1;
    w.descriptorType = type;
    ++count_;
    return w;
}

PushDescriptors& PushDescriptors::sampled(VkImageView view, VkImageLayout layout, VkSampler sampler) {
    VkWriteDescriptorSet& w = next(VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER);
    images_[w.dstBinding] = {sampler, view, layout};
    w.pImageInfo = &images_[w.dstBinding];
    return *this;
}

PushDescriptors& PushDescriptors::storageImage(VkImageView view) {
    VkWriteDescriptorSet& w = next(VK_DESCRIPTOR_TYPE_STORAGE_IMAGE);
    images_[w.dstBinding] = {VK_NULL_HANDLE, view, VK_IMAGE_LAYOUT_GENERAL};
    w.pImageInfo = &images_[w.dstBinding];
    return *this;
}

PushDescriptors& PushDescriptors::storageBuffer(VkBuffer buffer, VkDeviceSize offset, VkDeviceSize range) {
    VkWriteDescriptorSet& w = next(VK_DESCRIPTOR_TYPE_STORAGE_BUFFER);
    buffers_[w.dstBinding] = {buffer, offset, range};
    w.pBufferInfo = &buffers_[w.dstBinding];
    return *this;
}

PushDescriptors& PushDescriptors::uniformBuffer(VkBuffer buffer, VkDeviceSize offset, VkDeviceSize range) {
    VkWriteDescriptorSet& w = next(VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER);
    buffers_[w.dstBinding] = {buffer, offset, range};
    w.pBufferInfo = &buffers_[w.dstBinding];
    return *this;
}

PushDescriptors& PushDescriptors::accelerationStructure(VkAccelerationStructureKHR tlas) {
    VkWriteDescriptorSet& w = next(VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR);
    structures_[w.dstBinding] = tlas;
    VkWriteDescriptorSetAccelerationStructureKHR& as = structureWrites_[w.dstBinding];
    as = {VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET_ACCELERATION_STRUCTURE_KHR};
    as.accelerationStructureCount = 1;
    as.pAccelerationStructures = &structures_[w.dstBinding];
    w.pNext = &as;
    return *this;
}

void PushDescriptors::push(VkCommandBuffer cmd, const Pipeline& pipeline) {
    VkDescriptorType given[kMax];
    for (uint32_t i = 0; i < count_; ++i) given[i] = writes_[i].descriptorType;
    const uint32_t count = std::exchange(count_, 0u);  // reusable even after a failed check
    checkBindings(pipeline.name(), {}, pipeline.bindingTypes(), {given, count});
    fn_(cmd, pipeline.bindPoint(), pipeline.layout(), 0, count, writes_);
}

void Samplers::create(const vk::Context& ctx) {
    auto make = [&](VkFilter filter, VkSamplerAddressMode mode, bool aniso, bool compare, const char* name) {
        VkSamplerCreateInfo ci{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
        ci.magFilter = ci.minFilter = filter;
        ci.mipmapMode = filter == VK_FILTER_LINEAR ? VK_SAMPLER_MIPMAP_MODE_LINEAR : VK_SAMPLER_MIPMAP_MODE_NEAREST;
        ci.addressModeU = ci.addressModeV = ci.addressModeW = mode;
        ci.maxLod = VK_LOD_CLAMP_NONE;
        ci.anisotropyEnable = aniso ? VK_TRUE : VK_FALSE;
        ci.maxAnisotropy = aniso ? 8.0f : 1.0f;
        ci.compareEnable = compare ? VK_TRUE : VK_FALSE;
        ci.compareOp = VK_COMPARE_OP_GREATER_OR_EQUAL;
        ci.borderColor = VK_BORDER_COLOR_FLOAT_OPAQUE_WHITE;
        VkSampler s;
        VK_CHECK(vkCreateSampler(ctx.device(), &ci, nullptr, &s));
        ctx.name(s, VK_OBJECT_TYPE_SAMPLER, name);
        return s;
    };
    linearClamp = make(VK_FILTER_LINEAR, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE, false, false, "linear clamp");
    nearestClamp = make(VK_FILTER_NEAREST, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE, false, false, "nearest clamp");
    linearRepeatAniso = make(VK_FILTER_LINEAR, VK_SAMPLER_ADDRESS_MODE_REPEAT, true, false, "material");
    shadowCompare = make(VK_FILTER_LINEAR, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_BORDER, false, true, "shadow compare");
}

void Samplers::destroy(const vk::Context& ctx) {
    for (VkSampler s : {linearClamp, nearestClamp, linearRepeatAniso, shadowCompare})
        if (s) vkDestroySampler(ctx.device(), s, nullptr);
    *this = {};
}

}  // namespace ppr::shader
