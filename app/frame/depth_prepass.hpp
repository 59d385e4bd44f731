#pragma once
// depth_prepass=auto: whether the G-buffer's depth pre-pass (passes/gbuffer/gbuffer_pass.hpp) pays
// for itself. It costs what its triangles cost to transform and rasterise once more, and saves the
// shading of every layer drawn over another, which grows with the pixels. On lavapipe at 1280x720
// (docs/performance.md): the default scene, 20 589 opaque triangles, 0.68-0.80x the G-buffer with it;
// the scale scene, 1 115 138, 1.13x. Auto draws it while the opaque, unmasked triangles number at
// most a quarter of the frame's pixels (230 400 at 1280x720). Not measured on a GPU.
#include "settings/frame_settings.hpp"

#include <cstdint>

namespace ppr::app {

constexpr bool depthPrepassWanted(DepthPrepass mode, uint64_t opaqueTriangles, uint64_t pixels) {
    if (mode != DepthPrepass::Auto) return mode == DepthPrepass::On;
    return opaqueTriangles * 4 <= pixels;
}

}  // namespace ppr::app
