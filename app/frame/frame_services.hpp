#pragma once
// What the trunk shares with the technique modules: the device, the GPU scene, the reflector set, the
// frame constants (with mirrored views on request), the glass atlas, the tile-classification and
// depth-hierarchy passes more than one technique uses, the per-slot PPR counters buffer and the
// environment the misses fall back to (the reflection probe).
#include "common/frame.h"
#include "frame/environment_probe.hpp"
#include "frame/frame_constants.hpp"
#include "frame/frame_resources.hpp"
#include "frame/glass_atlas_frame.hpp"
#include "frame/reflector_set.hpp"
#include "glass_reflect/glass_reflect_pass.hpp"
#include "graph/blackboard.hpp"
#include "hiz/hiz_pass.hpp"
#include "lighting/lighting_pass.hpp"
#include "ppr_common/tiles.h"
#include "settings/frame_settings.hpp"
#include "tile_classify/tile_classify_pass.hpp"

#include <optional>
#include <vector>

namespace ppr::app {

// PprFrameStats per frame in flight: tile classification adds its counts, PPR its culling counts;
// host-read after the slot's fence.
class FrameStatsBuffers {
public:
    FrameStatsBuffers(const vk::Context& ctx, uint32_t framesInFlight);
    ~FrameStatsBuffers();
    FrameStatsBuffers(const FrameStatsBuffers&) = delete;
    FrameStatsBuffers& operator=(const FrameStatsBuffers&) = delete;
    void beginFrame(uint32_t slot) { written_[slot] = false; }
    graph::BufferHandle import(graph::RenderGraph& g, uint32_t slot) { return g.importBuffer("ppr.stats", &imports_[slot]); }
    void markWritten(uint32_t slot) { written_[slot] = true; }  // the counters are meaningful (PPR ran)
    std::optional<gpu::PprFrameStats> read(uint32_t slot) const;

private:
    const vk::Context& ctx_;
    std::vector<vk::Buffer> buffers_;
    std::vector<graph::ExternalBuffer> imports_;
    std::vector<bool> written_;
};

struct FrameServices {
    const vk::Context& ctx;
    const gpu::GpuScene& scene;
    const passes::GBufferPass& gbufferPass;
    const passes::LightingPass& lightingPass;
    ReflectorSet& reflectors;
    FrameConstantsBuffer& constants;
    GlassAtlasFrame& glass;
    FrameStatsBuffers& stats;
    const passes::TileClassifyPass& tileClassify;
    const passes::HizPass& hiz;
    const passes::GlassReflectPass& glassReflect;  // PPR's glass resolve; the trunk's atlas debug view
    EnvironmentProbe& environment;                 // --set fallback_env / env_source
    uint32_t framesInFlight;                       // per-slot resources a module keeps (the animated TLAS's instances)
};

// One technique's view of the frame being recorded.
struct TechniqueFrame {
    graph::RenderGraph& graph;
    graph::Blackboard& board;
    FrameServices& services;
    const FrameSettings& settings;
    const passes::FrameInputs& in;
    const passes::GBuffer& gbuffer;
    graph::ImageHandle lit;
    graph::ImageHandle shadowMap;
    uint32_t slot = 0;
    scene::CameraPose camera;

    VkBuffer reflectorData() const { return services.reflectors.buffer().reflectors(slot); }
    // The depth hierarchy of this frame's depth (built once, published as DepthHierarchy; on top of
    // DepthHierarchyTiles when PPR's reach pass stored those).
    passes::HizAtlas depthHierarchy();
    // Tile lists of this frame; reflector ids above maxReflectorId do not make a tile planar.
    passes::TileLists classifyTiles(uint32_t maxReflectorId);
    // The same with the arguments and stats cleared in the technique's batch (TileClassifyPass::queueClears).
    passes::TileLists classifyTiles(uint32_t maxReflectorId, const passes::TileClassifyTargets& cleared);
    // What this frame's misses fall back to (--set fallback_env, env_source), bound once a frame
    // (published as EnvironmentBound); renders the reflection probe the first time it is asked for.
    passes::Environment environment();
};

}  // namespace ppr::app
