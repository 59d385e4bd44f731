#pragma once
// What every pass needs from the frame besides graph resources: the frame constants (a host-written
// uniform buffer, one per frame in flight, outside the graph), shared samplers and the GPU scene.
#include "gpu/gpu_scene.hpp"
#include "shader/pipeline.hpp"

namespace ppr::passes {

class ImageClear;

struct FrameInputs {
    VkBuffer frameConstants = VK_NULL_HANDLE;
    VkDeviceSize frameConstantsOffset = 0;
    VkDeviceSize frameConstantsSize = 0;
    const shader::Samplers* samplers = nullptr;
    const gpu::GpuScene* scene = nullptr;
    // This frame's draw records (gpu::DrawData) and per-object motion (gpu::MotionData): an animated
    // scene's change per frame in flight (gpu/scene_motion.hpp).
    VkBuffer draws = VK_NULL_HANDLE, motion = VK_NULL_HANDLE;
    VkExtent2D extent{};
    // Surfaces → reflectors (common/surface_binding.hpp): per-draw ids, the reflectors (ReflectorData[])
    // and the loose ones the G-buffer tests per pixel.
    VkBuffer drawReflectors = VK_NULL_HANDLE, reflectors = VK_NULL_HANDLE, looseReflectors = VK_NULL_HANDLE;
    uint32_t looseCount = 0;
    VkBuffer looseGlassReflectors = VK_NULL_HANDLE;  // and the glass ones the glass forward pass tests per pixel
    uint32_t looseGlassCount = 0;
    // How passes clear images (common/clear_pass.hpp): ImageClear's compute clear, or a transfer clear.
    const ImageClear* clear = nullptr;
    bool computeClear = false;
    bool depthPrepass = false;  // the G-buffer pass draws depth alone first (gbuffer/gbuffer_pass.hpp)
};

// Vertex layout of scene::Vertex for the mesh passes.
std::vector<VkVertexInputAttributeDescription> sceneVertexAttributes(bool positionOnly);

// Records the opaque, unmasked draws with a depth-only `pipeline` whose set 0 is the frame constants
// and the draw records (the shadow map, the G-buffer's pre-pass), of `subset` (GpuScene::drawOpaque).
void drawUnmaskedDepth(const vk::Context& ctx, VkCommandBuffer cmd, const shader::Pipeline& pipeline, const FrameInputs& in,
                       gpu::GpuScene::Subset subset = gpu::GpuScene::Subset::All);

}  // namespace ppr::passes
