#pragma once
// What every pass needs from the frame besides graph resources: the frame constants (a host-written
// uniform buffer, one per frame in flight, outside the graph), shared samplers and the GPU scene.
#include "gpu/gpu_scene.hpp"
#include "shader/pipeline.hpp"

namespace ppr::passes {

struct FrameInputs {
    VkBuffer frameConstants = VK_NULL_HANDLE;
    VkDeviceSize frameConstantsOffset = 0;
    VkDeviceSize frameConstantsSize = 0;
    const shader::Samplers* samplers = nullptr;
    const gpu::GpuScene* scene = nullptr;
    VkExtent2D extent{};
};

// Vertex layout of scene::Vertex for the mesh passes.
std::vector<VkVertexInputAttributeDescription> sceneVertexAttributes(bool positionOnly);

}  // namespace ppr::passes
