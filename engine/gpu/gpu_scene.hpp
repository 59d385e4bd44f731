#pragma once
// The scene on the GPU: vertex/index buffers, per-draw and per-material records, material textures
// (mipmapped, in one bindless descriptor set), all uploaded once at load time. An animated scene's
// moving draws are the exception: gpu/scene_motion.hpp rewrites their records per frame.
#include "gpu/scene_motion.hpp"
#include "scene/scene.hpp"
#include "vk/context.hpp"

#include <memory>
#include <optional>
#include <vector>

namespace ppr::gpu {

class GpuScene {
public:
    GpuScene(const vk::Context& ctx, const scene::Scene& scene, VkSampler materialSampler, uint32_t framesInFlight = 1);
    ~GpuScene();
    GpuScene(const GpuScene&) = delete;
    GpuScene& operator=(const GpuScene&) = delete;

    VkBuffer vertexBuffer() const { return vertices_.buffer; }
    VkBuffer indexBuffer() const { return indices_.buffer; }
    // The draw records (DrawData) and per-object motion table (MotionData) frame `slot` reads: one
    // GPU-only copy for a still scene, one host-visible copy per frame in flight for an animated one.
    VkBuffer drawBuffer(uint32_t slot) const { return motion_ ? motion_->draws(slot) : draws_.buffer; }
    VkBuffer motionBuffer(uint32_t slot) const { return motion_ ? motion_->motion(slot) : stillMotion_.buffer; }
    bool animated() const { return motion_ != nullptr; }
    // Poses the moving draws for frame `slot` (SceneMotion::pose); nothing for a still scene.
    void pose(uint32_t slot, std::optional<double> seconds, bool cut) {
        if (motion_) motion_->pose(slot, seconds, cut);
    }
    const SceneMotion* motion() const { return motion_.get(); }
    VkBuffer materialBuffer() const { return materials_.buffer; }
    VkDescriptorSetLayout textureSetLayout() const { return textureLayout_; }
    VkDescriptorSet textureSet() const { return textureSet_; }
    const scene::Scene& cpu() const { return scene_; }

    // Records the indexed draws of opaque materials (G-buffer, shadow map); `perDraw(i)` is called
    // before each draw (push constants). Transparent materials (glTF alphaMode BLEND: glass) are left
    // to the glass forward pass.
    template <class F>
    void drawOpaque(VkCommandBuffer cmd, F&& perDraw) const {
        bindGeometry(cmd);
        for (uint32_t i = 0; i < scene_.draws.size(); ++i)
            if (!transparent(i)) drawOne(cmd, i, perDraw);
    }
    // Records the given draws in the given order (the glass pass: back to front).
    template <class F>
    void drawInOrder(VkCommandBuffer cmd, const std::vector<uint32_t>& order, F&& perDraw) const {
        bindGeometry(cmd);
        for (uint32_t i : order) drawOne(cmd, i, perDraw);
    }
    bool transparent(uint32_t draw) const;
    bool masked(uint32_t draw) const;  // alphaMode MASK: cut out by base colour alpha
    bool moves(uint32_t draw) const;  // the animation moves it (scene::SceneAnimation::draws)
    // The opaque draws whose masked() equals `masked` (the shadow map draws the two kinds with two
    // pipelines), of `subset`: all, those the animation never moves, or those it moves (the kept
    // shadow map holds the still ones: app/frame/shadow_map_cache.hpp).
    enum class Subset { All, Still, Moving };
    template <class F>
    void drawOpaque(VkCommandBuffer cmd, bool masked, Subset subset, F&& perDraw) const {
        bindGeometry(cmd);
        for (uint32_t i = 0; i < scene_.draws.size(); ++i)
            if (!transparent(i) && this->masked(i) == masked && (subset == Subset::All || moves(i) == (subset == Subset::Moving)))
                drawOne(cmd, i, perDraw);
    }
    const std::vector<uint32_t>& transparentDraws() const { return transparentDraws_; }

private:
    void bindGeometry(VkCommandBuffer cmd) const {
        VkDeviceSize offset = 0;
        vkCmdBindVertexBuffers(cmd, 0, 1, &vertices_.buffer, &offset);
        vkCmdBindIndexBuffer(cmd, indices_.buffer, 0, VK_INDEX_TYPE_UINT32);
    }
    template <class F>
    void drawOne(VkCommandBuffer cmd, uint32_t i, F& perDraw) const {
        const scene::Mesh& m = scene_.meshes[scene_.draws[i].mesh];
        perDraw(i);
        vkCmdDrawIndexed(cmd, m.indexCount, 1, m.firstIndex, m.vertexOffset, 0);
    }
    void uploadTextures(VkSampler sampler);
    const vk::Context& ctx_;
    const scene::Scene& scene_;
    vk::Buffer vertices_, indices_, draws_, materials_, stillMotion_;
    std::unique_ptr<SceneMotion> motion_;
    std::vector<vk::Image> textures_;
    VkDescriptorSetLayout textureLayout_ = VK_NULL_HANDLE;
    VkDescriptorPool pool_ = VK_NULL_HANDLE;
    VkDescriptorSet textureSet_ = VK_NULL_HANDLE;
    std::vector<uint32_t> transparentDraws_;
    std::vector<uint32_t> movingDraws_;  // sorted
};

// Upload helper: copies `bytes` into a GPU-only buffer through a staging buffer (load time only).
vk::Buffer uploadBuffer(const vk::Context& ctx, const void* data, VkDeviceSize bytes, VkBufferUsageFlags usage,
                        const std::string& name);

}  // namespace ppr::gpu
