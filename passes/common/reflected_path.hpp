#pragma once
// The format of every reflected-path image (common/reflection.h: x = path length, y = the reflected
// point's motion slot and the planar reference's class bits).
#include <vulkan/vulkan.h>

namespace ppr::passes {

inline constexpr VkFormat kReflectedPathFormat = VK_FORMAT_R32G32_SFLOAT;

}  // namespace ppr::passes
