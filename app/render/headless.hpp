#pragma once
// Headless rendering: records frames through the Renderer, submits them two in flight, reads the
// final image back and collects per-pass GPU timestamps. Used by `ppr capture`, compare, bench and the
// GPU tests. It holds the caller's choices (technique, settings, A/B view) and hands them to every
// frame's request by value.
#include "metrics/compare_metrics.hpp"
#include "render/renderer.hpp"
#include "render/taps.hpp"
#include "util/image_io.hpp"

#include <map>
#include <optional>

namespace ppr::app {

struct CaptureResult {
    util::Rgba8Image image;
    FloatImage reflection;                       // when requested and the technique has one (else 0x0)
    FloatImage glassReflection;                  // the glass reflection atlas, when requested and the frame had one
    // planar only, when the reflection is requested: per pixel (x, y) of planar/planar.h's
    // planar.distance (reflected path length, classes), width × height × 2 floats; else empty.
    std::vector<float> reflectedPath;
    std::map<std::string, double> passMedianMs;  // per pass, median over the frames
    double totalMedianMs = 0.0;                  // median over frames of the per-frame sum
    uint32_t frames = 0;
    uint32_t timedFrames = 0;                    // frames whose timestamps came back (== frames)
    uint32_t medianFrames = 0;                   // frames the medians are over: the last ≤ 256 timed ones
    std::vector<std::string> passOrder;          // execution order
    std::string cullLog;
    std::string dot;
    std::string warning;                         // the renderer's, e.g. reflectors beyond PPR's budget
    std::optional<gpu::PprFrameStats> pprStats;  // tile and culling counts of the last frame (PPR only)
    std::optional<GlassStats> glass;             // the last frame's glass atlas (PPR with glass panels)
    std::optional<EnvironmentProbe::Stats> environmentProbe;  // once the renderer rendered its reflection probe
};

// Tests: one frame's G-buffer depth and, when the technique builds it, its depth hierarchy.
struct DepthCapture {
    uint32_t width = 0, height = 0;
    std::vector<float> depth;                 // reverse-Z (D32), width × height, rows top to bottom
    uint32_t atlasWidth = 0, atlasHeight = 0;  // 0x0 when the frame built no hierarchy
    std::vector<float> hizAtlas;              // r32f, hiz/hiz.h layout (texels outside the levels undefined)
};

class HeadlessRenderer {
public:
    HeadlessRenderer(const vk::Context& ctx, Renderer& renderer);
    ~HeadlessRenderer();
    HeadlessRenderer(const HeadlessRenderer&) = delete;
    HeadlessRenderer& operator=(const HeadlessRenderer&) = delete;

    // Renders `frames` frames (≥ 1) of the camera at the extent; the last one is read back (and its
    // reflection image too when `readReflection`). `newShot`: the first frame is a camera cut (TAA's
    // history is dropped); a camera path's later frames pass false to continue the shot.
    CaptureResult capture(const scene::CameraPose& camera, VkExtent2D extent, uint32_t frames, bool dumpGraph = false,
                          bool readReflection = false, bool newShot = true);
    // The supersampled reference of TAA: `samples` frames (taa off) each moved by the next Halton (2, 3)
    // jitter (scene::haltonJitter), their display images averaged per channel. Timings are not kept.
    util::Rgba8Image captureSupersampled(const scene::CameraPose& camera, VkExtent2D extent, uint32_t samples);
    // Renders one frame of the camera at the extent and reads back its depth and depth hierarchy.
    DepthCapture captureDepth(const scene::CameraPose& camera, VkExtent2D extent);

    // The choices of the following captures. Throws std::runtime_error for an unknown technique.
    void setTechnique(const std::string& technique);
    const std::string& technique() const { return technique_; }
    Settings& settings() { return settings_; }
    const Settings& settings() const { return settings_; }
    // A table row with its own settings ("ppr@normalmap=off"): sets the technique, applies the
    // settings over the current ones and returns those, for the caller to restore after its captures.
    Settings setVariant(const std::string& variant);
    // The scene time of the following captures (animated scenes): seconds on the animation's clock;
    // none (the default) renders the pose as loaded.
    void setSceneTime(std::optional<double> seconds) { sceneTime_ = seconds; }
    // The reference A/B compares with (default planar).
    void setReference(const std::string& reference) { reference_ = reference; }
    // Frames rendered at this fraction of the extent and upscaled into the extent-sized final image,
    // as the viewer's render scale does (tests; render/render_scale.hpp). Captures that also read the
    // reflection back need 1.
    void setRenderScale(float scale) { renderScale_ = scale; }
    // The viewer's A/B view for the following captures (tests).
    void setAb(AbView view, float split) {
        ab_ = view;
        abSplit_ = split;
    }

private:
    void ensureTargets(VkExtent2D extent);
    // Resets the slot's fence and command buffer and begins recording (the slot must be idle).
    VkCommandBuffer beginSlot(uint32_t slot);
    const vk::Context& ctx_;
    Renderer& renderer_;
    VkCommandPool pool_ = VK_NULL_HANDLE;
    VkCommandBuffer cmds_[Renderer::kFramesInFlight]{};
    VkFence fences_[Renderer::kFramesInFlight]{};
    bool slotBusy_[Renderer::kFramesInFlight]{};
    // A persistent offscreen target imported into every frame's graph, like a swapchain image: the
    // frame's output is observable, so the graph keeps all passes even on frames not read back.
    vk::Image target_;
    graph::ExternalImage targetImport_;
    vk::Buffer readback_;
    graph::ExternalBuffer readbackImport_;
    vk::Buffer reflectionReadback_;  // RGBA16F
    graph::ExternalBuffer reflectionImport_;
    vk::Buffer pathReadback_;  // RG32F (planar's ReflectedPath)
    graph::ExternalBuffer pathImport_;
    vk::Buffer glassReadback_;       // RGBA16F, the glass atlas (sized on first use, grown with --set glass_atlas)
    graph::ExternalBuffer glassImport_;
    uint32_t glassReadbackSize_ = 0;
    std::string technique_ = "none";
    std::string reference_ = "planar";
    Settings settings_;
    AbCompareTaps abTaps_;
    AbView ab_ = AbView::Off;
    float abSplit_ = 0.5f;
    std::optional<glm::vec2> jitter_;  // captureSupersampled's current sample
    std::optional<double> sceneTime_;
    float renderScale_ = 1.0f;
    void ensureGlassReadback(uint32_t atlasSize);
};

}  // namespace ppr::app
