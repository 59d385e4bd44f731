#pragma once
// A cube-compatible image (6 layers, one mip) with two views: a cube view to sample it and a 2D-array
// view to write its faces from compute shaders (the reflection probe, app/frame/environment_probe.hpp).
#include "vk/context.hpp"

namespace ppr::vk {

struct CubeImage {
    VkImage image = VK_NULL_HANDLE;
    VkImageView cubeView = VK_NULL_HANDLE;    // samplerCube
    VkImageView layersView = VK_NULL_HANDLE;  // image2DArray, layer = face (+X −X +Y −Y +Z −Z)
    VmaAllocation allocation = VK_NULL_HANDLE;
    VkFormat format = VK_FORMAT_UNDEFINED;
    uint32_t size = 0;      // texels per face side
    VkDeviceSize bytes = 0;  // device memory it holds
};
CubeImage createCubeImage(const Context& ctx, uint32_t size, VkFormat format, VkImageUsageFlags usage, const std::string& name);
void destroyCubeImage(const Context& ctx, CubeImage& image);

}  // namespace ppr::vk
