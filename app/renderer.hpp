#pragma once
// Builds and records one frame: shadow → gbuffer → lighting → composite → tonemap → [ui] →
// [readback], all through the render graph. Owns everything created once per run (pipelines,
// samplers, the GPU scene, the graph executor and its pool, per-frame constant buffers).
#include "composite/composite_pass.hpp"
#include "gbuffer/gbuffer_pass.hpp"
#include "graph/executor.hpp"
#include "lighting/lighting_pass.hpp"
#include "settings.hpp"
#include "shadow/shadow_pass.hpp"
#include "tonemap/tonemap_pass.hpp"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace ppr::app {

struct FrameRequest {
    scene::CameraPose camera;
    VkExtent2D extent{};
    graph::ExternalImage* target = nullptr;      // tonemapped output (swapchain image) or null → transient
    graph::ExternalBuffer* readback = nullptr;   // when set, the final image is copied here (RGBA8)
    // Extra passes drawn on top of the final image (the viewer's ImGui); returns the new version.
    std::function<graph::ImageHandle(graph::RenderGraph&, graph::ImageHandle)> overlay;
    bool dumpGraph = false;  // keep the Graphviz text of this frame's graph
};

struct FrameRecord {
    std::string dot;      // when requested
    std::string cullLog;  // passes the graph culled, if any
};

class Renderer {
public:
    static constexpr uint32_t kFramesInFlight = 2;
    static constexpr VkFormat kCaptureFormat = VK_FORMAT_R8G8B8A8_UNORM;

    Renderer(const vk::Context& ctx, const scene::Scene& scene);
    ~Renderer();

    Settings& settings() { return settings_; }
    const Settings& settings() const { return settings_; }
    void prepareTargetFormat(VkFormat format) { tonemap_->prepare(format); }

    // Records the frame for `slot` into cmd (the caller begins/ends/submits cmd).
    FrameRecord record(VkCommandBuffer cmd, uint32_t slot, const FrameRequest& request);
    // Per-pass GPU times of the frame last recorded in `slot` (call after its fence signalled).
    std::vector<graph::PassTiming> timings(uint32_t slot) { return executor_->readTimings(slot); }

    const graph::GraphExecutor& executor() const { return *executor_; }
    graph::GraphExecutor& executor() { return *executor_; }  // the viewer trims the transient pool after resizes

private:
    void writeFrameConstants(uint32_t slot, const FrameRequest& request);
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
    std::unique_ptr<graph::GraphExecutor> executor_;
    vk::Buffer frameConstants_;
    VkDeviceSize frameStride_ = 0;
    uint32_t frameIndex_ = 0;
};

}  // namespace ppr::app
