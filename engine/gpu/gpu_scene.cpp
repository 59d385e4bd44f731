#include "gpu/gpu_scene.hpp"

#include "gpu/scene_data.h"
#include "vk/live_objects.hpp"

#include <glm/gtc/matrix_inverse.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstring>

namespace ppr::gpu {

static_assert(sizeof(VertexData) == sizeof(scene::Vertex) && offsetof(VertexData, position) == offsetof(scene::Vertex, position) &&
                  offsetof(VertexData, normal) == offsetof(scene::Vertex, normal) &&
                  offsetof(VertexData, tangent) == offsetof(scene::Vertex, tangent) && offsetof(VertexData, uv) == offsetof(scene::Vertex, uv0) &&
                  offsetof(VertexData, color) == offsetof(scene::Vertex, color),
              "gpu::VertexData (scene_data.h) must match scene::Vertex");

vk::Buffer uploadBuffer(const vk::Context& ctx, const void* data, VkDeviceSize bytes, VkBufferUsageFlags usage,
                        const std::string& name) {
    bytes = std::max<VkDeviceSize>(bytes, 16);  // empty scenes still get a valid (tiny) buffer
    vk::Buffer dst = vk::createBuffer(ctx, bytes, usage | VK_BUFFER_USAGE_TRANSFER_DST_BIT, vk::MemoryUse::GpuOnly, name);
    vk::Buffer staging = vk::createBuffer(ctx, bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, vk::MemoryUse::Upload, name + " staging");
    std::memset(staging.mapped, 0, bytes);
    if (data) std::memcpy(staging.mapped, data, bytes);
    vmaFlushAllocation(ctx.allocator(), staging.allocation, 0, VK_WHOLE_SIZE);
    ctx.immediateSubmit([&](VkCommandBuffer cmd) {
        VkBufferCopy region{0, 0, bytes};
        vkCmdCopyBuffer(cmd, staging.buffer, dst.buffer, 1, &region);
        // Load-time upload: make the copy visible to every later use (frames are separate submits).
        VkMemoryBarrier2 mb{VK_STRUCTURE_TYPE_MEMORY_BARRIER_2};
        mb.srcStageMask = VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT;
        mb.srcAccessMask = VK_ACCESS_2_TRANSFER_WRITE_BIT;
        mb.dstStageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
        mb.dstAccessMask = VK_ACCESS_2_MEMORY_READ_BIT;
        VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
        dep.memoryBarrierCount = 1;
        dep.pMemoryBarriers = &mb;
        vkCmdPipelineBarrier2(cmd, &dep);
    });
    vk::destroyBuffer(ctx, staging);
    return dst;
}

bool GpuScene::transparent(uint32_t draw) const {
    return std::binary_search(transparentDraws_.begin(), transparentDraws_.end(), draw);
}

bool GpuScene::moves(uint32_t draw) const { return std::binary_search(movingDraws_.begin(), movingDraws_.end(), draw); }

bool GpuScene::masked(uint32_t draw) const {
    const scene::DrawItem& d = scene_.draws[draw];
    if (d.mesh >= scene_.meshes.size()) return false;
    const int m = scene_.meshes[d.mesh].material;
    return m >= 0 && size_t(m) < scene_.materials.size() && scene_.materials[size_t(m)].masked;
}

GpuScene::GpuScene(const vk::Context& ctx, const scene::Scene& scene, VkSampler materialSampler, uint32_t framesInFlight)
    : ctx_(ctx), scene_(scene) {
    // Storage: ray-query hits read their triangle's vertices. With ray queries, also the input of the
    // acceleration-structure builds (gpu/acceleration_structures.hpp), which take device addresses.
    VkBufferUsageFlags geometryUsage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
    if (ctx.rayQuery().available)
        geometryUsage |= VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_BUILD_INPUT_READ_ONLY_BIT_KHR | VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT;
    vertices_ = uploadBuffer(ctx, scene.vertices.data(), scene.vertices.size() * sizeof(scene::Vertex),
                             VK_BUFFER_USAGE_VERTEX_BUFFER_BIT | geometryUsage, "scene vertices");
    indices_ = uploadBuffer(ctx, scene.indices.data(), scene.indices.size() * sizeof(uint32_t), VK_BUFFER_USAGE_INDEX_BUFFER_BIT | geometryUsage,
                            "scene indices");

    std::vector<DrawData> draws;
    for (const scene::DrawItem& d : scene.draws) {
        DrawData g{};
        g.world = d.world;
        g.normalMatrix = glm::mat4(glm::inverseTranspose(glm::mat3(d.world)));
        const scene::Mesh& m = scene.meshes[d.mesh];
        g.material = m.material >= 0 ? static_cast<uint32_t>(m.material) : static_cast<uint32_t>(scene.materials.size());
        g.reflectorId = d.reflector >= 0 ? static_cast<uint32_t>(d.reflector) + 1 : 0;
        g.firstIndex = m.firstIndex;
        g.vertexOffset = m.vertexOffset;
        g.flags = m.vertexColors ? kDrawVertexColors : 0u;
        if (m.material >= 0 && scene.materials[size_t(m.material)].transparent)
            transparentDraws_.push_back(static_cast<uint32_t>(draws.size()));
        draws.push_back(g);
    }
    const scene::SceneAnimation& animation = scene.animation;
    for (size_t i = 0; i < animation.draws.size(); ++i) draws[animation.draws[i]].motionSlot = SceneMotion::slotOf(i);
    movingDraws_ = animation.draws;
    std::sort(movingDraws_.begin(), movingDraws_.end());
    if (animation.empty()) draws_ = uploadBuffer(ctx, draws.data(), draws.size() * sizeof(DrawData), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, "scene draws");
    else motion_ = std::make_unique<SceneMotion>(ctx, scene, draws, framesInFlight);
    const MotionData identity{glm::mat4(1.0f)};
    stillMotion_ = uploadBuffer(ctx, &identity, sizeof identity, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, "scene motion (still)");

    auto tex = [](int i) { return i >= 0 ? static_cast<uint32_t>(i) : kNoTexture; };
    std::vector<MaterialData> materials;
    for (const scene::Material& m : scene.materials) {
        MaterialData g{};
        g.baseColor = m.baseColorFactor;
        g.metallic = m.metallicFactor;
        g.roughness = m.roughnessFactor;
        g.normalScale = m.normalScale;
        g.flags = (m.reflective ? kMaterialReflective : 0u) | (m.transparent ? kMaterialTransparent : 0u) | (m.masked ? kMaterialMasked : 0u);
        g.alphaCutoff = m.alphaCutoff;
        g.baseColorTex = tex(m.baseColorTexture);
        g.normalTex = tex(m.normalTexture);
        g.metalRoughTex = tex(m.metallicRoughnessTexture);
        g.uvRow0 = glm::vec4(m.uvRow0, 0.0f);
        g.uvRow1 = glm::vec4(m.uvRow1, 0.0f);
        g.emissive = m.emissiveFactor;
        g.emissiveTex = tex(m.emissiveTexture);
        materials.push_back(g);
    }
    // Default material (for primitives without one) sits at the end.
    MaterialData fallback{glm::vec4(0.8f), 0.0f, 0.8f, 1.0f, 0u, kNoTexture, kNoTexture, kNoTexture, 0.5f, glm::vec4(1, 0, 0, 0), glm::vec4(0, 1, 0, 0),
                          glm::vec3(0.0f), kNoTexture};
    materials.push_back(fallback);
    materials_ = uploadBuffer(ctx, materials.data(), materials.size() * sizeof(MaterialData), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                              "scene materials");
    uploadTextures(materialSampler);
}

void GpuScene::uploadTextures(VkSampler sampler) {
    // Material textures are sampled by fragment shaders and by the ray-traced reference's compute pass.
    constexpr VkPipelineStageFlags2 kSampledStages = VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;
    const uint32_t count = std::max<uint32_t>(1, static_cast<uint32_t>(scene_.textures.size()));
    // Fragment shaders (G-buffer, glass) and compute (the ray-traced reference shades its hits).
    VkDescriptorSetLayoutBinding binding{0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, count,
                                         VK_SHADER_STAGE_FRAGMENT_BIT | VK_SHADER_STAGE_COMPUTE_BIT, nullptr};
    VkDescriptorBindingFlags flags = VK_DESCRIPTOR_BINDING_PARTIALLY_BOUND_BIT;
    VkDescriptorSetLayoutBindingFlagsCreateInfo bfi{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_BINDING_FLAGS_CREATE_INFO};
    bfi.bindingCount = 1;
    bfi.pBindingFlags = &flags;
    VkDescriptorSetLayoutCreateInfo lci{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    lci.pNext = &bfi;
    lci.bindingCount = 1;
    lci.pBindings = &binding;
    VK_CHECK(vkCreateDescriptorSetLayout(ctx_.device(), &lci, nullptr, &textureLayout_));
    ++vk::liveObjects().descriptorSetLayouts;
    ctx_.name(textureLayout_, VK_OBJECT_TYPE_DESCRIPTOR_SET_LAYOUT, "material textures");
    VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, count};
    VkDescriptorPoolCreateInfo pci{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    pci.maxSets = 1;
    pci.poolSizeCount = 1;
    pci.pPoolSizes = &size;
    VK_CHECK(vkCreateDescriptorPool(ctx_.device(), &pci, nullptr, &pool_));
    ++vk::liveObjects().descriptorPools;
    VkDescriptorSetAllocateInfo ai{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    ai.descriptorPool = pool_;
    ai.descriptorSetCount = 1;
    ai.pSetLayouts = &textureLayout_;
    VK_CHECK(vkAllocateDescriptorSets(ctx_.device(), &ai, &textureSet_));

    std::vector<VkDescriptorImageInfo> infos;
    for (const scene::TextureImage& t : scene_.textures) {
        const uint32_t mips = static_cast<uint32_t>(std::floor(std::log2(std::max(t.width, t.height)))) + 1;
        const VkFormat format = t.srgb ? VK_FORMAT_R8G8B8A8_SRGB : VK_FORMAT_R8G8B8A8_UNORM;
        vk::Image img = vk::createImage(ctx_, {t.width, t.height}, format,
                                        VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT, mips,
                                        "texture " + t.name);
        const VkDeviceSize bytes = t.rgba8.size();
        vk::Buffer staging = vk::createBuffer(ctx_, bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, vk::MemoryUse::Upload, "texture staging");
        std::memcpy(staging.mapped, t.rgba8.data(), bytes);
        vmaFlushAllocation(ctx_.allocator(), staging.allocation, 0, VK_WHOLE_SIZE);
        ctx_.immediateSubmit([&](VkCommandBuffer cmd) {
            auto barrier = [&](uint32_t mip, VkImageLayout from, VkImageLayout to, VkPipelineStageFlags2 srcStage, VkAccessFlags2 srcAccess,
                               VkPipelineStageFlags2 dstStage, VkAccessFlags2 dstAccess) {
                VkImageMemoryBarrier2 b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
                b.srcStageMask = srcStage;
                b.srcAccessMask = srcAccess;
                b.dstStageMask = dstStage;
                b.dstAccessMask = dstAccess;
                b.oldLayout = from;
                b.newLayout = to;
                b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
                b.image = img.image;
                b.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, mip, 1, 0, 1};
                VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
                dep.imageMemoryBarrierCount = 1;
                dep.pImageMemoryBarriers = &b;
                vkCmdPipelineBarrier2(cmd, &dep);
            };
            for (uint32_t m = 0; m < mips; ++m)
                barrier(m, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_PIPELINE_STAGE_2_NONE, 0,
                        VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT);
            VkBufferImageCopy copy{};
            copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
            copy.imageExtent = {t.width, t.height, 1};
            vkCmdCopyBufferToImage(cmd, staging.buffer, img.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &copy);
            // Mip chain by successive linear blits.
            int32_t w = static_cast<int32_t>(t.width), h = static_cast<int32_t>(t.height);
            for (uint32_t m = 1; m < mips; ++m) {
                barrier(m - 1, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
                        VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_READ_BIT);
                VkImageBlit blit{};
                blit.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, m - 1, 0, 1};
                blit.srcOffsets[1] = {w, h, 1};
                w = std::max(1, w / 2);
                h = std::max(1, h / 2);
                blit.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, m, 0, 1};
                blit.dstOffsets[1] = {w, h, 1};
                vkCmdBlitImage(cmd, img.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, img.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &blit,
                               VK_FILTER_LINEAR);
                barrier(m - 1, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
                        VK_ACCESS_2_TRANSFER_READ_BIT, kSampledStages, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
            }
            barrier(mips - 1, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
                    VK_ACCESS_2_TRANSFER_WRITE_BIT, kSampledStages, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
        });
        vk::destroyBuffer(ctx_, staging);
        infos.push_back({sampler, img.view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL});
        textures_.push_back(img);
    }
    if (!infos.empty()) {
        VkWriteDescriptorSet w{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
        w.dstSet = textureSet_;
        w.dstBinding = 0;
        w.descriptorCount = static_cast<uint32_t>(infos.size());
        w.descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
        w.pImageInfo = infos.data();
        vkUpdateDescriptorSets(ctx_.device(), 1, &w, 0, nullptr);
    }
}

GpuScene::~GpuScene() {
    vkDeviceWaitIdle(ctx_.device());
    for (vk::Image& t : textures_) vk::destroyImage(ctx_, t);
    motion_.reset();
    for (vk::Buffer* b : {&vertices_, &indices_, &draws_, &materials_, &stillMotion_}) vk::destroyBuffer(ctx_, *b);
    if (pool_) vkDestroyDescriptorPool(ctx_.device(), pool_, nullptr), --vk::liveObjects().descriptorPools;
    if (textureLayout_) vkDestroyDescriptorSetLayout(ctx_.device(), textureLayout_, nullptr), --vk::liveObjects().descriptorSetLayouts;
}

}  // namespace ppr::gpu
