#pragma once
// The scene on the GPU: vertex/index buffers, per-draw and per-material records, material textures
// (mipmapped, in one bindless descriptor set), all uploaded once at load time — nothing per frame.
#include "scene/scene.hpp"
#include "vk/context.hpp"

#include <vector>

namespace ppr::gpu {

class GpuScene {
public:
    GpuScene(const vk::Context& ctx, const scene::Scene& scene, VkSampler materialSampler);
    ~GpuScene();
    GpuScene(const GpuScene&) = delete;
    GpuScene& operator=(const GpuScene&) = delete;

    VkBuffer vertexBuffer() const { return vertices_.buffer; }
    VkBuffer indexBuffer() const { return indices_.buffer; }
    VkBuffer drawBuffer() const { return draws_.buffer; }
    VkBuffer materialBuffer() const { return materials_.buffer; }
    VkDescriptorSetLayout textureSetLayout() const { return textureLayout_; }
    VkDescriptorSet textureSet() const { return textureSet_; }
    const scene::Scene& cpu() const { return scene_; }

    // Records the indexed draws; `perDraw(i)` is called before each draw (push constants).
    template <class F>
    void drawAll(VkCommandBuffer cmd, F&& perDraw) const {
        VkDeviceSize offset = 0;
        vkCmdBindVertexBuffers(cmd, 0, 1, &vertices_.buffer, &offset);
        vkCmdBindIndexBuffer(cmd, indices_.buffer, 0, VK_INDEX_TYPE_UINT32);
        for (uint32_t i = 0; i < scene_.draws.size(); ++i) {
            const scene::Mesh& m = scene_.meshes[scene_.draws[i].mesh];
            perDraw(i);
            vkCmdDrawIndexed(cmd, m.indexCount, 1, m.firstIndex, m.vertexOffset, 0);
        }
    }

private:
    void uploadTextures(VkSampler sampler);
    const vk::Context& ctx_;
    const scene::Scene& scene_;
    vk::Buffer vertices_, indices_, draws_, materials_;
    std::vector<vk::Image> textures_;
    VkDescriptorSetLayout textureLayout_ = VK_NULL_HANDLE;
    VkDescriptorPool pool_ = VK_NULL_HANDLE;
    VkDescriptorSet textureSet_ = VK_NULL_HANDLE;
};

// Upload helper: copies `bytes` into a GPU-only buffer through a staging buffer (load time only).
vk::Buffer uploadBuffer(const vk::Context& ctx, const void* data, VkDeviceSize bytes, VkBufferUsageFlags usage,
                        const std::string& name);

}  // namespace ppr::gpu
