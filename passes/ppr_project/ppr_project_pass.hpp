#pragma once
// PPR projection pass (ppr_project.comp): scatters every pixel's offset into the intermediate buffer,
// one workgroup per screen tile, with optional per-tile reflector culling.
#include "common/frame_inputs.hpp"
#include "common/workgroup_widths.hpp"
#include "graph/graph.hpp"

#include <optional>
#include "ppr_project/project_threads.hpp"

namespace ppr::passes {

struct ReflectorBinding {  // the reflector buffers of the frame's slot (common/reflector_buffer.hpp)
    VkBuffer reflectors = VK_NULL_HANDLE;
    VkBuffer order = VK_NULL_HANDLE;
    VkBuffer planeLeaders = VK_NULL_HANDLE;  // a reflector per cull plane
    uint32_t count = 0;                      // reflectors projected (≤ kPprMaxReflectors)
    uint32_t cullPlanes = 0;
};

// The tiles the projection is dispatched on indirectly (ppr_reach/ppr_reach_pass.hpp), and the
// buffers that pass wrote before it.
struct PprTileList {
    graph::BufferHandle args;           // TileDispatchArgs (ppr_common/tiles.h)
    graph::BufferHandle tiles;          // args.x packed tiles
    graph::BufferHandle tileSurvivors;  // 0 for every tile left out
    graph::BufferHandle stats;          // PprFrameStats, tilesWithContent counted
};

struct PprProjectInputs {
    graph::ImageHandle depth;
    graph::ImageHandle intermediate;  // cleared
    graph::BufferHandle bounds;       // ppr.bounds outputs: the rectangles
    graph::BufferHandle visible;      // and the reflectors on screen (PprVisibleCounts and lists)
    graph::BufferHandle stats;        // PprFrameStats (counters added to)
    uint32_t tilesX = 0, tilesY = 0;
    bool cullTiles = true;            // --set tiles
    graph::ImageHandle glassAtlas;    // r32ui, cleared (glass panels' intermediate buffer)
    graph::BufferHandle glassRegions;  // GlassRegionData per reflector (glass_reflect/glass_regions.hpp)
    bool glass = true;                // --set glass
    graph::ImageHandle normal;        // G-buffer normal (read with facingOnly)
    bool facingOnly = true;           // --set facing
    bool splat = true;                // --set splat: magnified surfaces fill between their landings
    uint32_t threads = 0;             // invocations per tile, one of kProjectThreadChoices; 0: autoThreads
    std::optional<PprTileList> reach;  // dispatch on these tiles only (tiles=1, indirect=1); else on every tile
};

struct PprProjectOutputs {
    graph::ImageHandle intermediate;
    graph::BufferHandle tileSurvivors;  // uint per tile: reflectors surviving culling (debug=tiles)
    graph::BufferHandle stats;
    graph::ImageHandle glassAtlas;
};

class PprProjectPass {
public:
    explicit PprProjectPass(const vk::Context& ctx);
    PprProjectOutputs add(graph::RenderGraph& g, const FrameInputs& in, const ReflectorBinding& reflectors, const PprProjectInputs& inputs) const;
    // What threads = 0 means on this device: kPprProjectThreads on a CPU, kPprProjectThreadsGpu elsewhere.
    static uint32_t autoThreads(const vk::DeviceInfo& device);

private:
    const vk::Context& ctx_;
    WidthPipelines pipelines_;
};

}  // namespace ppr::passes
