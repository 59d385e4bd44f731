#pragma once
// The render scale (`ppr view --render-scale S`, the viewer panel's "render scale"): the frame is
// rendered at S times the output's size and the tonemap pass upscales it into the output image (the
// swapchain's), so a CPU device (lavapipe) stays interactive in a large window; the panel and the
// editor's handles stay at the window's resolution. Pure logic, unit-tested without a device.
#include "cli/cli.hpp"  // kMinRenderScale: --render-scale's range

#include <vulkan/vulkan.h>

#include <glm/vec2.hpp>

#include <array>
#include <string_view>

namespace ppr::app {

// The panel's choices (the command line takes any value in [kMinRenderScale, 1]).
constexpr std::array<float, 5> kRenderScaleChoices{1.0f, 0.75f, 0.5f, 0.33f, 0.25f};

// `--render-scale auto` (the default): a GPU renders at the window's own resolution; a CPU device
// (lavapipe) at half of it per side, where a 1280x720 window's PPR frame takes 63 ms instead of 167
// (README): exploring at 6 frames a second is not exploring. The panel and the start-up line say so.
constexpr float kCpuDeviceRenderScale = 0.5f;
inline float defaultRenderScale(std::string_view deviceType) { return deviceType == "cpu" ? kCpuDeviceRenderScale : 1.0f; }

// The render extent for an output (window) extent: each side scaled and rounded, at least 1 pixel.
VkExtent2D scaledExtent(VkExtent2D window, float scale);

// The render pixel under window pixel `p` (the one whose footprint holds p's centre), clamped to
// the render extent.
glm::ivec2 renderPixelOf(glm::ivec2 p, VkExtent2D window, VkExtent2D render);

}  // namespace ppr::app
