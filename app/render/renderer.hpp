#pragma once
// Builds and records one frame: shadow → gbuffer → lighting → [reflection technique] → composite →
// tonemap → [ui] → [readback], all through the render graph. Techniques: none, ppr (classify → clear →
// project → reflect → [ssr-hiz fallback on non-planar tiles]), ssr-brute / ssr-lowq / ssr-hiz /
// ssr-linear (classify → [hierarchy] → march), floor (the cost floor), planar (mirrored re-render per
// plane, the ground truth). Owns everything created once per run (pipelines,
// samplers, the GPU scene, the graph executor and its pool, per-frame constant buffers).
#include "common/frame.h"
#include "common/reflector_buffer.hpp"
#include "common/surface_binding.hpp"
#include "ab_compare/ab_compare_pass.hpp"
#include "composite/composite_pass.hpp"
#include "floor/floor_pass.hpp"
#include "hiz/hiz_pass.hpp"
#include "gbuffer/gbuffer_pass.hpp"
#include "glass_forward/glass_forward_pass.hpp"
#include "glass_reflect/glass_reflect_pass.hpp"
#include "glass_reflect/glass_regions.hpp"
#include "graph/executor.hpp"
#include "lighting/lighting_pass.hpp"
#include "planar/planar_pass.hpp"
#include "ppr_bounds/ppr_bounds_pass.hpp"
#include "ppr_common/tiles.h"
#include "pick/pick_pass.hpp"
#include "ppr_project/ppr_project_pass.hpp"
#include "ppr_reflect/ppr_reflect_pass.hpp"
#include "settings.hpp"
#include "shadow/shadow_pass.hpp"
#include "ssr_common/ssr_trace_pass.hpp"
#include "tile_classify/tile_classify_pass.hpp"
#include "tonemap/tonemap_pass.hpp"

#include <functional>
#include <optional>
#include <memory>
#include <string>
#include <vector>

namespace ppr::app {

// The viewer's A/B comparison of the current technique with the planar ground truth.
enum class AbView { Off, Split, ErrorHeat };

struct FrameRequest {
    scene::CameraPose camera;
    VkExtent2D extent{};
    graph::ExternalImage* target = nullptr;      // tonemapped output (swapchain image) or null → transient
    graph::ExternalBuffer* readback = nullptr;   // when set, the final image is copied here (RGBA8)
    // When set and the technique produces one, the reflection image is copied here (RGBA16F,
    // common/reflection.h) — what `ppr compare` scores.
    graph::ExternalBuffer* reflectionReadback = nullptr;
    // Tests: the G-buffer depth (D32 floats) and, when the frame builds it, the depth hierarchy's
    // atlas (r32f, hiz/hiz.h layout) copied here.
    graph::ExternalBuffer* depthReadback = nullptr;
    graph::ExternalBuffer* hizReadback = nullptr;
    // When set and the frame has a glass reflection atlas, it is copied here (RGBA16F, glass_atlas² texels).
    graph::ExternalBuffer* glassReadback = nullptr;
    // Extra passes drawn on top of the final image (the viewer's ImGui); returns the new version.
    std::function<graph::ImageHandle(graph::RenderGraph&, graph::ImageHandle)> overlay;
    bool dumpGraph = false;  // keep the Graphviz text of this frame's graph
    // A/B (a technique other than planar/none): also render the planar ground truth and show it right
    // of abSplit (a fraction of the width), or the technique's reflection error as a heat map.
    AbView ab = AbView::Off;
    float abSplit = 0.5f;
    // The reflector editor: the G-buffer under this pixel (passes/pick/pick.h PickResult) into `pickResult`.
    std::optional<glm::ivec2> pickPixel;
    graph::ExternalBuffer* pickResult = nullptr;
};

struct FrameRecord {
    std::string dot;      // when requested
    std::string cullLog;  // passes the graph culled, if any
    std::string warning;  // e.g. a technique that could not run at this size (shown by the viewer)
    bool reflectionCopied = false;
    bool hizCopied = false;
    bool glassCopied = false;
};


// What the glass atlas held in a PPR frame (report.json "glass", the viewer).
struct GlassStats {
    uint32_t atlasSize = 0;  // texels per side (--set glass_atlas)
    uint32_t visible = 0;    // glass panels on screen
    uint32_t scaled = 0;     // regions scaled down to fit (overflow)
    uint32_t dropped = 0;    // panels without a region (overflow: the farthest first)
    float scale = 1.0f;      // the common scale of the regions
    std::vector<scene::GlassRegion> layout;  // where each panel's region lies (screen and atlas)
    uint32_t regions() const { return static_cast<uint32_t>(layout.size()); }  // panels with a region
    uint32_t usedHeight() const;  // atlas rows holding regions (the rest is not dispatched)
    bool overflowed() const { return scaled > 0 || dropped > 0; }
    // One line saying how the atlas overflowed ("" when it did not).
    std::string overflowMessage() const;
};

class Renderer {
public:
    static constexpr uint32_t kFramesInFlight = 2;
    static constexpr VkFormat kCaptureFormat = VK_FORMAT_R8G8B8A8_UNORM;

    Renderer(const vk::Context& ctx, const scene::Scene& scene);
    ~Renderer();

    Settings& settings() { return settings_; }
    const Settings& settings() const { return settings_; }
    // Throws std::runtime_error for a name not in techniqueNames() (techniques.hpp).
    void setTechnique(const std::string& technique);
    const std::string& technique() const { return technique_; }
    // The reflector set used from the next recorded frame on (uploaded once per change).
    void setReflectors(std::vector<scene::Reflector> reflectors);
    const std::vector<scene::Reflector>& reflectors() const { return reflectorList_; }
    void prepareTargetFormat(VkFormat format) { tonemap_->prepare(format); }

    // Records the frame for `slot` into cmd (the caller begins/ends/submits cmd).
    FrameRecord record(VkCommandBuffer cmd, uint32_t slot, const FrameRequest& request);
    // Per-pass GPU times of the frame last recorded in `slot` (call after its fence signalled).
    std::vector<graph::PassTiming> timings(uint32_t slot) { return executor_->readTimings(slot); }
    // Tile and culling counters of the frame last recorded in `slot` (after its fence), when it ran PPR.
    std::optional<gpu::PprFrameStats> frameStats(uint32_t slot) const;
    // Set while the reflector set exceeds PPR's budget (kPprMaxReflectors): says which are ignored.
    const std::string& reflectorWarning() const { return reflectorWarning_; }
    // Glass atlas counters of the frame last recorded in `slot`, when it ran PPR with glass panels.
    std::optional<GlassStats> glassStats(uint32_t slot) const { return glassStats_[slot]; }

    const graph::GraphExecutor& executor() const { return *executor_; }
    graph::GraphExecutor& executor() { return *executor_; }  // the viewer trims the transient pool after resizes

private:
    struct Views {  // main view + the planar technique's mirrored views of this frame
        std::vector<passes::PlanarView> planar;
    };
    gpu::FrameConstants mainConstants(const FrameRequest& request) const;
    void ensureViewCapacity(uint32_t views);
    passes::FrameInputs frameInputs(uint32_t slot, uint32_t view, VkExtent2D extent) const;
    // Mirrored views (one per visible plane group) when `mirroredViews` (planar, or A/B against it).
    Views writeFrameConstants(uint32_t slot, const FrameRequest& request, bool mirroredViews);
    std::optional<graph::ImageHandle> addReflection(graph::RenderGraph& g, const std::string& technique, uint32_t slot,
                                                    const passes::FrameInputs& in, const passes::GBuffer& gb, graph::ImageHandle lit,
                                                    graph::ImageHandle shadowMap, const Views& views, const FrameRequest& req,
                                                    FrameRecord& rec);
    uint32_t pprResolveFlags() const;  // holes / filter / antibleed
    // Packs this frame's glass atlas (glassStats_, the region table's CPU copy); returns the atlas
    // size (1 without glass). Users add the table's upload (glassRegions_.add) when they read it.
    uint32_t prepareGlass(uint32_t slot, const FrameRequest& req);
    void addGlassAtlas(graph::RenderGraph& g, uint32_t slot, const FrameRequest& req, passes::PprProjectInputs& project);
    passes::HizAtlas addHiz(graph::RenderGraph& g, const passes::FrameInputs& in, const passes::GBuffer& gb, const FrameRequest& req,
                            FrameRecord& rec);
    passes::SsrInputs ssrInputs(const passes::GBuffer& gb, graph::ImageHandle lit, uint32_t slot, const passes::TileLists& tiles) const;
    const passes::SsrTracePass* ssrPass(const std::string& technique) const;
    const vk::Context& ctx_;
    const scene::Scene& scene_;
    Settings settings_;
    shader::Samplers samplers_;
    std::unique_ptr<gpu::GpuScene> gpuScene_;
    std::unique_ptr<passes::ShadowPass> shadow_;
    std::unique_ptr<passes::GBufferPass> gbuffer_;
    std::unique_ptr<passes::LightingPass> lighting_;
    std::unique_ptr<passes::CompositePass> composite_;
    std::unique_ptr<passes::TonemapPass> tonemap_;
    std::unique_ptr<passes::PprProjectPass> pprProject_;
    std::unique_ptr<passes::PprReflectPass> pprReflect_;
    std::unique_ptr<passes::PprBoundsPass> pprBounds_;
    std::unique_ptr<passes::TileClassifyPass> tileClassify_;
    std::unique_ptr<passes::SsrTracePass> ssrBrute_, ssrLowq_, ssrHiz_, ssrLinear_;
    std::unique_ptr<passes::HizPass> hiz_;
    std::unique_ptr<passes::FloorPass> floor_;
    std::unique_ptr<passes::GlassForwardPass> glass_;
    std::unique_ptr<passes::AbComparePass> ab_;
    std::unique_ptr<passes::PickPass> pick_;
    std::unique_ptr<passes::GlassReflectPass> glassReflect_;
    passes::GlassRegionTable glassRegions_;                  // this frame's atlas layout, uploaded by the graph
    passes::GlassRegionBuffers glassRegionBuffers_;          // its graph buffers (valid while recording)
    std::vector<uint32_t> glassIndices_;                     // glass reflectors among those PPR projects
    std::optional<passes::GlassReflection> glassReflection_;  // this frame's, when PPR resolved one
    std::optional<GlassStats> glassStats_[kFramesInFlight];
    glm::mat4 frameViewProj_{1.0f};                           // the main view's, of the frame being recorded
    std::vector<bool> glassPlaneGroups_;                      // plane groups holding a pane with a region (planar)
    std::vector<uint32_t> glassOrder_;  // this frame's transparent draws, back to front (reused)
    vk::Buffer stats_[kFramesInFlight];  // PprFrameStats, host-read after the slot's fence
    graph::ExternalBuffer statsImport_[kFramesInFlight];
    bool statsWritten_[kFramesInFlight]{};
    std::string reflectorWarning_;
    std::unique_ptr<passes::PlanarPass> planar_;
    std::unique_ptr<passes::ReflectorBuffer> reflectorBuffer_;
    std::unique_ptr<passes::SurfaceBindingBuffer> surfaces_;  // which reflector each surface belongs to
    std::unique_ptr<graph::GraphExecutor> executor_;
    std::string technique_ = "none";
    std::vector<scene::Reflector> reflectorList_;
    uint64_t reflectorVersion_ = 0;
    vk::Buffer frameConstants_;  // kFramesInFlight × viewCapacity_ FrameConstants, host-written
    VkDeviceSize frameStride_ = 0;
    uint32_t viewCapacity_ = 0;
    uint32_t frameIndex_ = 0;
};

}  // namespace ppr::app
