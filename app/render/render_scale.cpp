#include "render/render_scale.hpp"

#include <algorithm>
#include <cmath>

namespace ppr::app {

VkExtent2D scaledExtent(VkExtent2D window, float scale) {
    auto side = [scale](uint32_t n) {
        return std::max<uint32_t>(1u, static_cast<uint32_t>(std::lround(static_cast<double>(n) * static_cast<double>(scale))));
    };
    return {side(window.width), side(window.height)};
}

glm::ivec2 renderPixelOf(glm::ivec2 p, VkExtent2D window, VkExtent2D render) {
    auto axis = [](int v, uint32_t from, uint32_t to) {
        if (from == 0u || to == 0u) return 0;
        const double centre = (static_cast<double>(v) + 0.5) * static_cast<double>(to) / static_cast<double>(from);
        return std::clamp(static_cast<int>(std::floor(centre)), 0, static_cast<int>(to) - 1);
    };
    return {axis(p.x, window.width, render.width), axis(p.y, window.height, render.height)};
}

}  // namespace ppr::app
