#pragma once
// The ray-traced reference's passes (technique `raytraced`): compute shaders with ray queries against
// the scene's TLAS (gpu/acceleration_structures.hpp), hits shaded with the lighting pass's code.
//   raytraced.reflect      every reflector pixel's mirror ray → the reflection image (common/reflection.h)
//   raytraced.glass.clear  the glass reflection atlas cleared to "no reflection"
//   raytraced.glass        every glass pane's atlas texel's mirror ray → the atlas (PPR's / planar's layout)
//   raytraced.tlas         animated scenes only: the TLAS rebuilt with this frame's pose
#include "common/frame_inputs.hpp"
#include "gbuffer/gbuffer_pass.hpp"
#include "gpu/acceleration_structures.hpp"
#include "graph/graph.hpp"

#include <optional>

namespace ppr::passes {

// What every ray-traced pass reads besides its own inputs.
struct RaytraceInputs {
    graph::ImageHandle depth;      // the main view's depth (visibility of hits in the main view)
    graph::ImageHandle shadowMap;  // the lighting pass's shadow map
    VkBuffer reflectors = VK_NULL_HANDLE;  // this frame slot's ReflectorData[]
    VkAccelerationStructureKHR tlas = VK_NULL_HANDLE;
    std::optional<graph::BufferHandle> tlasBuilt;  // the TLAS's storage as this frame's rebuild left it (animated scenes)
    bool rasterCoverage = false;  // rt_coverage=raster: flat mirrors and the glass atlas decide silhouettes as the rasterizer does (raster_coverage.glsl)
};

// This frame's glass atlas layout (glass_reflect/glass_regions.hpp).
struct RaytraceGlass {
    graph::BufferHandle regions, regionList;
    uint32_t regionCount = 0, atlasSize = 0;
    VkExtent2D used{};  // the atlas texels holding regions, from its corner: the rest is not dispatched
};

class RaytracePass {
public:
    static constexpr VkFormat kReflectionFormat = VK_FORMAT_R16G16B16A16_SFLOAT;
    RaytracePass(const vk::Context& ctx, const gpu::GpuScene& scene);
    // "raytraced.reflect": the reflection of every reflector pixel; `normalMapped` reflects about the
    // G-buffer's normal instead of the reflector's plane. `distanceOut`: also each pixel's reflected
    // path length, eye → reflector → hit (R32F, 0 = none; TAA's virtual point).
    graph::ImageHandle addScreen(graph::RenderGraph& g, const FrameInputs& in, const RaytraceInputs& rt, const GBuffer& gb,
                                 bool normalMapped, graph::ImageHandle* distanceOut = nullptr) const;
    // "raytraced.glass.clear" + "raytraced.glass": the panes' reflections in the atlas layout.
    graph::ImageHandle addGlass(graph::RenderGraph& g, const FrameInputs& in, const RaytraceInputs& rt, const RaytraceGlass& glass) const;
    // "raytraced.tlas": rebuilds `structures`' TLAS for frame `slot` with the scene's current pose
    // (animated scenes); returns the TLAS storage for RaytraceInputs::tlasBuilt. Call once per frame.
    graph::BufferHandle addTlasRebuild(graph::RenderGraph& g, gpu::SceneAccelerationStructures& structures, const gpu::GpuScene& scene,
                                       uint32_t slot);

private:
    const vk::Context& ctx_;
    shader::Pipeline screen_[2], glass_[2];  // [rt_coverage=raster]: its own pipelines (a specialization constant)
    // The graph keeps the TLAS storage's and the scratch's last access here from frame to frame.
    graph::ExternalBuffer tlasStorage_, scratch_;
};

}  // namespace ppr::passes
