#pragma once
// The trunk: shadow → gbuffer → lighting → [the request's technique] → composite → glass → [taa] → tonemap,
// all through the render graph, with the request's taps attached at their points. The request
// carries the frame's choices by value (technique, settings); the renderer keeps only what lives
// across frames: pipelines, the GPU scene, the reflector set, per-slot buffers, the technique modules.
#include "common/clear_pass.hpp"
#include "composite/composite_pass.hpp"
#include "frame/shadow_map_cache.hpp"
#include "frame/technique.hpp"
#include "glass_forward/glass_forward_pass.hpp"
#include "graph/executor.hpp"
#include "render/frame_tap.hpp"
#include "settings/settings.hpp"
#include "shadow/shadow_pass.hpp"
#include "taa/taa_pass.hpp"
#include "tonemap/tonemap_pass.hpp"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace ppr::app {

struct FrameRequest {
    scene::CameraPose camera;
    VkExtent2D extent{};
    std::string technique = "none";  // a techniqueTable() name
    std::string reference = "planar";  // the ground truth taps compare with (a reference row of the table)
    FrameSettings settings = Settings().values();
    // Tonemapped output (swapchain image) or null → transient. A target larger than `extent` (the
    // viewer's render scale) is filled by upscaling the frame.
    graph::ExternalImage* target = nullptr;
    std::vector<FrameTap> taps;
    bool dumpGraph = false;  // keep the Graphviz text of this frame's graph
    // TAA: a camera cut (a jump, not motion) drops the history. `jitter` overrides the sub-pixel
    // offset in pixels whatever taa says (the supersampled reference's samples).
    bool cameraCut = false;
    std::optional<glm::vec2> jitter;
    // Animated scenes: the time on the animation's clock, in seconds; none = the pose as loaded (every
    // capture of a named camera, so a still image never depends on when it was taken).
    std::optional<double> sceneTime;
};

struct FrameRecord {
    std::string dot;      // when requested
    std::string cullLog;  // passes the graph culled, if any
    std::string warning;  // e.g. a technique that could not run at this size (shown by the viewer)
};

class Renderer {
public:
    static constexpr uint32_t kFramesInFlight = 2;
    static constexpr VkFormat kCaptureFormat = VK_FORMAT_R8G8B8A8_UNORM;

    Renderer(const vk::Context& ctx, const scene::Scene& scene);
    ~Renderer();

    // The reflector set used from the next recorded frame on (uploaded once per change).
    void setReflectors(std::vector<scene::Reflector> reflectors);
    const std::vector<scene::Reflector>& reflectors() const { return reflectors_->list(); }
    void prepareTargetFormat(VkFormat format) { tonemap_->prepare(format); }

    // Records the frame for `slot` into cmd (the caller begins/ends/submits cmd). Throws
    // std::runtime_error for a technique not in the table.
    FrameRecord record(VkCommandBuffer cmd, uint32_t slot, const FrameRequest& request);
    // Why `technique` cannot render frames of this size on this device, "" when it can
    // (Technique::unsupported; e.g. raytraced on a device without VK_KHR_ray_query).
    std::string unsupported(const std::string& technique, VkExtent2D extent) const;
    // Per-pass GPU times of the frame last recorded in `slot` (call after its fence signalled).
    std::vector<graph::PassTiming> timings(uint32_t slot) { return executor_->readTimings(slot); }
    // Tile and culling counters of the frame last recorded in `slot` (after its fence), when it ran PPR.
    std::optional<gpu::PprFrameStats> frameStats(uint32_t slot) const { return stats_->read(slot); }
    // Set while the reflector set exceeds PPR's budget (kPprMaxReflectors): says which are ignored.
    const std::string& reflectorWarning() const { return reflectors_->budgetWarning(); }
    // Glass atlas counters of the frame last recorded in `slot`, when it packed a glass atlas.
    const std::optional<GlassStats>& glassStats(uint32_t slot) const { return glass_->stats(slot); }

    // The reflection probe (--set env_source=probe): how often it was rendered, its cost and placement.
    const EnvironmentProbe& environmentProbe() const { return *environment_; }
    // The kept shadow maps (shadow_cache=1): how many frames drew them.
    const ShadowMapCache& shadowMapCache() const { return *shadowCache_; }

    const graph::GraphExecutor& executor() const { return *executor_; }
    graph::GraphExecutor& executor() { return *executor_; }  // the viewer trims the transient pool after resizes

private:
    Technique* module(const std::string& technique) const;
    void resetTaaHistory(const FrameRequest& req);
    static void runTaps(const FrameRequest& req, TapPoint point, TapContext& ctx);

    const vk::Context& ctx_;
    const scene::Scene& scene_;
    shader::Samplers samplers_;
    std::unique_ptr<gpu::GpuScene> gpuScene_;
    std::unique_ptr<passes::ShadowPass> shadow_;
    std::unique_ptr<ShadowMapCache> shadowCache_;
    std::unique_ptr<passes::GBufferPass> gbuffer_;
    std::unique_ptr<passes::LightingPass> lighting_;
    std::unique_ptr<passes::CompositePass> composite_;
    std::unique_ptr<passes::GlassForwardPass> glassForward_;
    std::unique_ptr<passes::TonemapPass> tonemap_;
    std::unique_ptr<passes::TaaPass> taa_;
    std::unique_ptr<passes::TileClassifyPass> tileClassify_;
    std::unique_ptr<passes::HizPass> hiz_;
    std::unique_ptr<passes::GlassReflectPass> glassReflect_;
    std::unique_ptr<ReflectorSet> reflectors_;
    std::unique_ptr<passes::ImageClear> imageClear_;
    std::unique_ptr<FrameConstantsBuffer> constants_;
    std::unique_ptr<GlassAtlasFrame> glass_;
    std::unique_ptr<FrameStatsBuffers> stats_;
    std::unique_ptr<EnvironmentProbe> environment_;
    std::unique_ptr<FrameServices> services_;
    std::vector<std::unique_ptr<Technique>> modules_;  // one per techniqueTable() row (null: none)
    std::unique_ptr<graph::GraphExecutor> executor_;
    std::vector<uint32_t> glassOrder_;  // this frame's transparent draws, back to front (reused)
    uint32_t taaFrames_ = 0;            // TAA frames recorded: the jitter sequence's position
    std::string lastTechnique_;         // a technique change drops TAA's history
    bool lastTaaSplit_ = true;          // so does taa_split: its history holds the surface part alone
    bool lastTaaStillRange_ = true;     // and taa_still_range: the spread images hold a range or moments
};

}  // namespace ppr::app
