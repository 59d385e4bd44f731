#pragma once
// The viewer's ImGui side: the ImGui context with its GLFW + Vulkan (1.86, render-pass based)
// backends drawn through passes::UiPass, and the "ppr" panel
// (device, frame times, cameras, vsync, every --set setting, GPU timing table, capture).
#include "ppr_common/tiles.h"
#include "render/renderer.hpp"
#include "render/taps.hpp"
#include "cli/scene_source.hpp"
#include "techniques/technique_table.hpp"
#include "ui/ui_pass.hpp"
#include "viewer/timing_history.hpp"

#include <optional>
#include <string>
#include <vector>

struct GLFWwindow;

namespace ppr::app {

// ImGui context and backends. The Vulkan backend is initialised against UiPass's render pass for the
// swapchain format (re-initialised if a recreated swapchain changes format).
class ImGuiLayer {
public:
    ImGuiLayer(const vk::Context& ctx, GLFWwindow* window, passes::UiPass& ui, VkFormat format, uint32_t imageCount);
    ~ImGuiLayer();
    ImGuiLayer(const ImGuiLayer&) = delete;
    ImGuiLayer& operator=(const ImGuiLayer&) = delete;

    void swapchainChanged(VkFormat format, uint32_t imageCount);  // device must be idle
    void beginFrame();  // backends' NewFrame + ImGui::NewFrame
    void endFrame();    // ImGui::Render (the draw data is recorded by the next addPass)
    // The "ui" graph pass drawing the last endFrame()'s data over target.
    graph::ImageHandle addPass(graph::RenderGraph& g, graph::ImageHandle target);

    bool wantsMouse() const;
    bool wantsKeyboard() const;
    bool wantsTextInput() const;

private:
    void initVulkan(VkFormat format, uint32_t imageCount);
    void shutdownVulkan();
    const vk::Context& ctx_;
    passes::UiPass& ui_;
    VkDescriptorPool pool_ = VK_NULL_HANDLE;
    VkFormat format_ = VK_FORMAT_UNDEFINED;
    bool glfwBackend_ = false;
    bool vulkanBackend_ = false;
};

// What the panel shows and edits.
struct PanelModel {
    const vk::DeviceInfo* device = nullptr;
    VkExtent2D extent{};        // the window's
    VkExtent2D renderExtent{};  // the frame's (the window's times the render scale)
    float* renderScale = nullptr;  // edited in place (app/render/render_scale.hpp)
    double frameMs = 0.0;  // wall time per frame (average over the history)
    double cpuMs = 0.0;    // CPU time spent building + recording + submitting a frame
    double presentMs = 0.0;  // in vkQueuePresentKHR: waiting for vsync, or on a CPU device for the frame itself
    const std::vector<ResolvedCamera>* cameras = nullptr;
    int cameraIndex = -1;  // -1: free camera
    float cameraSpeed = 0.0f;
    bool vsync = true;
    bool* animate = nullptr;    // an animated scene: play (true) or hold its pose; null for a still scene
    double sceneSeconds = 0.0;  // its clock
    Settings* settings = nullptr;
    std::string technique;  // current; a change comes back in PanelActions::technique
    std::string warning;    // the renderer's, shown in the panel
    const TimingHistory* timings = nullptr;
    std::optional<gpu::PprFrameStats> pprStats;  // tile and culling counts of the last completed PPR frame
    std::optional<GlassStats> glassStats;        // its glass atlas (PPR with glass panels)
    uint32_t reflectors = 0, reflectorsProjected = 0;
    std::string shadowMap;  // frame/shadow_map_work.hpp shadowMapSummary: whether the frame reads a kept map
    std::string status;  // last capture result or settings error
    AbView* ab = nullptr;       // A/B with the reference (edited in place)
    float* abSplit = nullptr;   // split position, fraction of the width
    std::string* reference = nullptr;  // the ground truth A/B and hold-B show (a reference row of the table)
};

struct PanelActions {
    int jumpToCamera = -1;
    bool vsyncChanged = false;
    bool capture = false;
    std::string technique;  // non-empty: switch to it
};

PanelActions drawPanel(PanelModel& model);

// F2: next value of the `debug` setting (wraps around). Returns the new value.
std::string cycleDebugView(Settings& settings);
// F3: the technique after `current` in techniqueNames() (wraps around).
std::string nextTechnique(const std::string& current);

}  // namespace ppr::app
