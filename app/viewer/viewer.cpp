// `ppr view`: GLFW window + swapchain, fly camera, ImGui panel, frames recorded through the Renderer
// (the ImGui pass is the graph's overlay), captures on F12.
//
// Automation hooks (tests/ui):
//   PPR_VIEWER_FRAMES=N         exit by itself after N presented frames (exit code 0 unless validation errors)
//   PPR_VIEWER_SCREENSHOT_AT=N  save a capture (like F12) after frame N
//   SIGINT / SIGTERM            close the window cleanly (exit code 0 unless validation errors)
//   PPR_VIEWER_SOAK=1           drive itself: techniques, settings, window sizes; a memory sample at
//                               the end of each return to the initial state (viewer_soak.hpp)
//   PPR_MEMORY_LOG=N            print a memory sample every N frames (render/memory_log.hpp)
//   PPR_MEMORY_TEST_LEAK=N      leak N bytes a frame on purpose (the soak's own test)
#include "viewer/viewer.hpp"

#include "editor/editor_ui.hpp"
#include "frame/shadow_map_work.hpp"

#include "capture/report.hpp"
#include "cli/scene_source.hpp"
#include "render/headless.hpp"
#include "render/memory_log.hpp"
#include "render/render_scale.hpp"
#include "techniques/technique_table.hpp"
#include "viewer/viewer_soak.hpp"
#include "viewer/viewer_ui.hpp"
#include "vk/swapchain.hpp"

#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <deque>
#include <filesystem>
#include <memory>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>

namespace ppr::app {

bool displayAvailable() {
    if (!std::getenv("DISPLAY") && !std::getenv("WAYLAND_DISPLAY")) return false;
    if (!glfwInit()) return false;
    glfwTerminate();
    return true;
}

namespace {

using Clock = std::chrono::steady_clock;

// Positive integer from the environment; 0 when unset. A malformed value is an error naming the variable.
uint64_t envCount(const char* name) {
    const char* text = std::getenv(name);
    if (!text || !*text) return 0;
    char* end = nullptr;
    const unsigned long long v = std::strtoull(text, &end, 10);
    if (*end != '\0' || v == 0 || text[0] == '-')
        throw std::runtime_error(std::string(name) + "=" + text + ": expected a positive integer (frames)");
    return v;
}

volatile std::sig_atomic_t g_quit = 0;
void onQuitSignal(int) { g_quit = 1; }

// Ctrl+C / kill: leave the frame loop so the device is drained and validation is tallied.
struct QuitSignals {
    using Handler = void (*)(int);
    Handler oldInt, oldTerm;
    QuitSignals() : oldInt(std::signal(SIGINT, onQuitSignal)), oldTerm(std::signal(SIGTERM, onQuitSignal)) { g_quit = 0; }
    ~QuitSignals() {
        std::signal(SIGINT, oldInt == SIG_ERR ? SIG_DFL : oldInt);
        std::signal(SIGTERM, oldTerm == SIG_ERR ? SIG_DFL : oldTerm);
    }
};

void glfwError(int code, const char* text) { std::fprintf(stderr, "ppr: GLFW error %d: %s\n", code, text); }

struct GlfwSession {
    GlfwSession() {
        glfwSetErrorCallback(glfwError);
        if (!glfwInit()) throw std::runtime_error("view: cannot initialise GLFW (no usable display? use `ppr capture` headless)");
    }
    ~GlfwSession() { glfwTerminate(); }
};

// Input gathered by GLFW callbacks (installed before ImGui's, which chain to them).
struct InputEvents {
    float wheel = 0.0f;
    std::vector<EditorKey> editorKeys;  // editor shortcuts, in order
    int cycleDebug = 0;
    int cycleTechnique = 0;
    bool capture = false;
    bool resized = false;
    // Keys pressed with Ctrl (shortcuts), until released: not movement even when Ctrl goes up first
    // (xdotool's ctrl+s releases Ctrl before S; a frame in between saw S alone and moved the camera).
    std::set<int> shortcutKeys;
};

void onKey(GLFWwindow* w, int key, int, int action, int mods) {
    auto* in = static_cast<InputEvents*>(glfwGetWindowUserPointer(w));
    if (!in) return;
    if (action == GLFW_RELEASE) in->shortcutKeys.erase(key);
    if (action != GLFW_PRESS) return;
    if (mods & GLFW_MOD_CONTROL) in->shortcutKeys.insert(key);
    if (key == GLFW_KEY_F2) ++in->cycleDebug;
    if (key == GLFW_KEY_F3) ++in->cycleTechnique;
    if (key == GLFW_KEY_F12) in->capture = true;
    const bool ctrl = (mods & GLFW_MOD_CONTROL) != 0;
    if (ctrl && key == GLFW_KEY_Z) in->editorKeys.push_back((mods & GLFW_MOD_SHIFT) ? EditorKey::Redo : EditorKey::Undo);
    if (ctrl && key == GLFW_KEY_Y) in->editorKeys.push_back(EditorKey::Redo);
    if (ctrl && key == GLFW_KEY_S) in->editorKeys.push_back(EditorKey::Save);
    if (ctrl && key == GLFW_KEY_D) in->editorKeys.push_back(EditorKey::Duplicate);
    if (key == GLFW_KEY_DELETE) in->editorKeys.push_back(EditorKey::Delete);
}
void onScroll(GLFWwindow* w, double, double dy) {
    if (auto* in = static_cast<InputEvents*>(glfwGetWindowUserPointer(w))) in->wheel += static_cast<float>(dy);
}
void onFramebufferSize(GLFWwindow* w, int, int) {
    if (auto* in = static_cast<InputEvents*>(glfwGetWindowUserPointer(w))) in->resized = true;
}

// Everything of a viewer session except the Vulkan context (owned by runViewer so that validation
// messages raised while tearing these down are still counted). Members are destroyed in reverse order.
class Viewer {
public:
    Viewer(const Options& o, vk::Context& ctx, const scene::Scene& scene);
    ~Viewer();
    // maxFrames: exit after that many frames (0 = run until closed); captureAt: capture after that frame.
    void run(uint64_t maxFrames, uint64_t captureAt);

private:
    struct Window {
        GLFWwindow* handle = nullptr;
        ~Window() {
            if (handle) glfwDestroyWindow(handle);
        }
    };
    struct Surface {
        VkInstance instance = VK_NULL_HANDLE;
        VkSurfaceKHR handle = VK_NULL_HANDLE;
        ~Surface() {
            if (handle) vkDestroySurfaceKHR(instance, handle, nullptr);
        }
    };
    struct FrameSync {
        VkDevice device = VK_NULL_HANDLE;
        VkCommandPool pool = VK_NULL_HANDLE;
        VkCommandBuffer cmd[Renderer::kFramesInFlight]{};
        VkFence fence[Renderer::kFramesInFlight]{};
        VkSemaphore acquired[Renderer::kFramesInFlight]{};
        bool busy[Renderer::kFramesInFlight]{};  // submitted and its timings not read yet
        ~FrameSync() {
            if (!device) return;
            for (VkFence f : fence) vkDestroyFence(device, f, nullptr);
            for (VkSemaphore s : acquired) vkDestroySemaphore(device, s, nullptr);
            vkDestroyCommandPool(device, pool, nullptr);
        }
    };

    bool recreateSwapchain();  // false while minimised
    bool renderFrame(uint32_t slot);  // false when the frame was skipped (out of date)
    void updateCamera(float dt);
    void buildUi();
    void saveCapture();

    const Options& options_;
    vk::Context& ctx_;
    const scene::Scene& scene_;
    std::vector<ResolvedCamera> cameras_;  // every named camera, for the combo
    InputEvents input_;
    Window window_;
    Surface surface_;
    std::unique_ptr<vk::Swapchain> swapchain_;
    std::unique_ptr<Renderer> renderer_;
    std::unique_ptr<passes::UiPass> uiPass_;
    std::unique_ptr<ImGuiLayer> imgui_;
    FrameSync sync_;
    std::unique_ptr<HeadlessRenderer> headless_;  // captures, created on the first one
    // The user's choices, handed to every frame's request by value.
    std::string technique_;
    std::unique_ptr<ViewerSoak> soak_ = std::getenv("PPR_VIEWER_SOAK") ? std::make_unique<ViewerSoak>() : nullptr;
    std::string reference_ = "planar";  // what A/B, the heat map and hold-B compare with
    Settings settings_;
    std::unique_ptr<AbCompareTaps> abTaps_;
    std::unique_ptr<PickTap> pickTap_;

    scene::FlyCamera camera_;
    std::string cameraName_;
    int cameraIndex_ = -1;
    bool cameraCut_ = false;  // the next frame starts a new shot (a jump to a named camera)
    // An animated scene plays in real time unless paused in the panel; a still one has no clock.
    bool animate_ = true;
    double sceneClock_ = 0.0;  // seconds on the animation's clock
    bool vsync_ = true;
    float renderScale_ = 1.0f;  // the frame's size over the window's (--render-scale, the panel)
    bool swapchainDirty_ = false;
    bool looking_ = false;
    double lastCursorX_ = 0.0, lastCursorY_ = 0.0;
    TimingHistory timings_;
    std::optional<gpu::PprFrameStats> pprStats_;
    std::optional<GlassStats> glassStats_;
    AbView ab_ = AbView::Off;
    float abSplit_ = 0.5f;
    // The reflector editor: the document, its window, and the G-buffer pick a view click waits for.
    std::unique_ptr<ReflectorDocument> document_;
    std::unique_ptr<ReflectorEditorUi> editor_;
    vk::Buffer pickBuffer_[Renderer::kFramesInFlight];
    graph::ExternalBuffer pickImport_[Renderer::kFramesInFlight];
    bool pickIssued_[Renderer::kFramesInFlight]{};
    std::optional<ViewClick> pendingClick_;
    glm::ivec2 pickPixel_{0};
    std::deque<double> frameMs_, cpuMs_, presentMs_;
    double lastPresentMs_ = 0.0;  // renderFrame's vkQueuePresentKHR, which may wait for the frame
    std::string status_;
    std::string warning_;  // from the renderer (e.g. PPR refused at this size), shown in the panel
    bool captureRequested_ = false;
    uint64_t frames_ = 0;
};

Viewer::Viewer(const Options& o, vk::Context& ctx, const scene::Scene& scene)
    : options_(o), ctx_(ctx), scene_(scene), renderScale_(o.renderScale.value_or(defaultRenderScale(ctx.info().type))) {
    if (!o.renderScale && renderScale_ != 1.0f)
        std::printf("ppr: rendering at %.2f of the window's size on a %s device (--render-scale 1 for its full size)\n", renderScale_,
                    ctx.info().type.c_str());
    cameras_ = resolveCameras(scene, "");
    const ResolvedCamera start = resolveCameras(scene, o.camera).front();
    camera_.pose = start.pose;
    cameraName_ = start.name;
    for (size_t i = 0; i < cameras_.size(); ++i)
        if (!o.camera.empty() && cameras_[i].name == start.name) cameraIndex_ = static_cast<int>(i);
    if (o.camera.empty()) cameraIndex_ = 0;

    if (!glfwVulkanSupported()) throw std::runtime_error("view: GLFW found no Vulkan loader");
    glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
    const std::string title = "ppr \xE2\x80\x94 " + ctx.info().name;  // "ppr — <device>"
    window_.handle = glfwCreateWindow(static_cast<int>(o.width), static_cast<int>(o.height), title.c_str(), nullptr, nullptr);
    if (!window_.handle) throw std::runtime_error("view: cannot create a " + std::to_string(o.width) + "x" + std::to_string(o.height) + " window");
    glfwSetWindowUserPointer(window_.handle, &input_);
    glfwSetKeyCallback(window_.handle, onKey);
    glfwSetScrollCallback(window_.handle, onScroll);
    glfwSetFramebufferSizeCallback(window_.handle, onFramebufferSize);

    surface_.instance = ctx.instance();
    VK_CHECK(glfwCreateWindowSurface(ctx.instance(), window_.handle, nullptr, &surface_.handle));
    VkBool32 presentable = VK_FALSE;
    VK_CHECK(vkGetPhysicalDeviceSurfaceSupportKHR(ctx.physicalDevice(), ctx.queueFamily(), surface_.handle, &presentable));
    if (!presentable) throw std::runtime_error("view: " + ctx.info().name + " cannot present to this window (on Xvfb or a remote display try PPR_DEVICE=cpu)");

    swapchain_ = std::make_unique<vk::Swapchain>(ctx, surface_.handle);
    int fbw = 0, fbh = 0;
    glfwGetFramebufferSize(window_.handle, &fbw, &fbh);
    while (!swapchain_->recreate({static_cast<uint32_t>(fbw), static_cast<uint32_t>(fbh)}, vsync_)) {
        glfwWaitEventsTimeout(0.25);  // created minimised: wait for a size
        glfwGetFramebufferSize(window_.handle, &fbw, &fbh);
        if (glfwWindowShouldClose(window_.handle) || g_quit) throw std::runtime_error("view: window closed before it was shown");
    }

    renderer_ = std::make_unique<Renderer>(ctx, scene);
    document_ = std::make_unique<ReflectorDocument>(scene.reflectors, reflectorFilePath(o));
    editor_ = std::make_unique<ReflectorEditorUi>(*document_, scene);
    for (uint32_t i = 0; i < Renderer::kFramesInFlight; ++i) {
        pickBuffer_[i] = vk::createBuffer(ctx, sizeof(gpu::PickResult), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, vk::MemoryUse::Readback,
                                          "pick[" + std::to_string(i) + "]");
        pickImport_[i].buffer = pickBuffer_[i].buffer;
        pickImport_[i].desc = {sizeof(gpu::PickResult)};
        pickImport_[i].finalAccess = graph::Access::HostRead;
    }
    for (const std::string& kv : o.sets) settings_.apply(kv);
    technique_ = techniqueDesc(o.technique).name;
    abTaps_ = std::make_unique<AbCompareTaps>(ctx);
    pickTap_ = std::make_unique<PickTap>(ctx);
    renderer_->prepareTargetFormat(swapchain_->format());
    uiPass_ = std::make_unique<passes::UiPass>(ctx);
    imgui_ = std::make_unique<ImGuiLayer>(ctx, window_.handle, *uiPass_, swapchain_->format(), swapchain_->imageCount());

    sync_.device = ctx.device();
    VkCommandPoolCreateInfo pci{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    pci.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
    pci.queueFamilyIndex = ctx.queueFamily();
    VK_CHECK(vkCreateCommandPool(ctx.device(), &pci, nullptr, &sync_.pool));
    ctx.name(sync_.pool, VK_OBJECT_TYPE_COMMAND_POOL, "viewer frames");
    VkCommandBufferAllocateInfo ai{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    ai.commandPool = sync_.pool;
    ai.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    ai.commandBufferCount = Renderer::kFramesInFlight;
    VK_CHECK(vkAllocateCommandBuffers(ctx.device(), &ai, sync_.cmd));
    for (uint32_t i = 0; i < Renderer::kFramesInFlight; ++i) {
        VkFenceCreateInfo fci{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
        fci.flags = VK_FENCE_CREATE_SIGNALED_BIT;
        VK_CHECK(vkCreateFence(ctx.device(), &fci, nullptr, &sync_.fence[i]));
        VkSemaphoreCreateInfo sci{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
        VK_CHECK(vkCreateSemaphore(ctx.device(), &sci, nullptr, &sync_.acquired[i]));
        const std::string n = std::to_string(i);
        ctx.name(sync_.cmd[i], VK_OBJECT_TYPE_COMMAND_BUFFER, "viewer frame " + n);
        ctx.name(sync_.fence[i], VK_OBJECT_TYPE_FENCE, "viewer frame fence " + n);
        ctx.name(sync_.acquired[i], VK_OBJECT_TYPE_SEMAPHORE, "image acquired " + n);
    }
}

Viewer::~Viewer() {
    vkDeviceWaitIdle(ctx_.device());
    for (vk::Buffer& b : pickBuffer_) vk::destroyBuffer(ctx_, b);
}

bool Viewer::recreateSwapchain() {
    int w = 0, h = 0;
    glfwGetFramebufferSize(window_.handle, &w, &h);
    if (w == 0 || h == 0) return false;
    const VkFormat oldFormat = swapchain_->format();
    if (!swapchain_->recreate({static_cast<uint32_t>(w), static_cast<uint32_t>(h)}, vsync_)) return false;  // waits idle
    uiPass_->releaseFramebuffers();  // their views are gone
    if (swapchain_->format() != oldFormat) renderer_->prepareTargetFormat(swapchain_->format());
    imgui_->swapchainChanged(swapchain_->format(), swapchain_->imageCount());
    // Transients of the old size are no longer used by any frame (the device is idle).
    renderer_->executor().trimPool(0);
    swapchainDirty_ = false;
    return true;
}

void Viewer::updateCamera(float dt) {
    GLFWwindow* w = window_.handle;
    scene::FlyCameraInput in;
    in.dt = std::clamp(dt, 0.0f, 0.1f);
    auto key = [&](int k) { return glfwGetKey(w, k) == GLFW_PRESS && !input_.shortcutKeys.count(k) ? 1.0f : 0.0f; };
    // With Ctrl held the letters are the editor's shortcuts (Ctrl+S saves, Ctrl+Z undoes), not movement:
    // a Ctrl+S caught mid-press by a frame used to move the camera back a step.
    const bool ctrl = glfwGetKey(w, GLFW_KEY_LEFT_CONTROL) == GLFW_PRESS || glfwGetKey(w, GLFW_KEY_RIGHT_CONTROL) == GLFW_PRESS;
    if (!imgui_->wantsKeyboard() && !ctrl) {
        in.forward = key(GLFW_KEY_W) - key(GLFW_KEY_S);
        in.right = key(GLFW_KEY_D) - key(GLFW_KEY_A);
        in.up = key(GLFW_KEY_E) - key(GLFW_KEY_Q);
    }
    double x = 0.0, y = 0.0;
    glfwGetCursorPos(w, &x, &y);
    const bool rmb = glfwGetMouseButton(w, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS;
    if (rmb && !looking_ && !imgui_->wantsMouse()) looking_ = true;  // a drag that starts over the panel is the panel's
    else if (!rmb) looking_ = false;
    if (looking_) {
        in.mouseDx = static_cast<float>(x - lastCursorX_);
        in.mouseDy = static_cast<float>(y - lastCursorY_);
    }
    lastCursorX_ = x;
    lastCursorY_ = y;
    if (input_.wheel != 0.0f && !imgui_->wantsMouse()) camera_.scrollSpeed(input_.wheel);
    input_.wheel = 0.0f;

    const scene::CameraPose before = camera_.pose;
    camera_.update(in);
    if (camera_.pose.position != before.position || camera_.pose.yawDeg != before.yawDeg || camera_.pose.pitchDeg != before.pitchDeg) {
        cameraIndex_ = -1;
        cameraName_ = "free";
    }
}

void Viewer::buildUi() {
    imgui_->beginFrame();
    auto average = [](const std::deque<double>& d) {
        double s = 0.0;
        for (double v : d) s += v;
        return d.empty() ? 0.0 : s / static_cast<double>(d.size());
    };
    PanelModel m;
    m.device = &ctx_.info();
    m.extent = swapchain_->extent();
    m.renderExtent = scaledExtent(m.extent, renderScale_);
    m.renderScale = &renderScale_;
    m.frameMs = average(frameMs_);
    m.cpuMs = average(cpuMs_);
    m.presentMs = average(presentMs_);
    m.cameras = &cameras_;
    m.cameraIndex = cameraIndex_;
    m.cameraSpeed = camera_.speed;
    m.vsync = vsync_;
    if (!scene_.animation.empty()) {
        m.animate = &animate_;
        m.sceneSeconds = sceneClock_;
    }
    m.settings = &settings_;
    m.technique = technique_;
    m.warning = warning_;
    m.timings = &timings_;
    m.pprStats = pprStats_;
    m.ab = &ab_;
    m.abSplit = &abSplit_;
    m.reference = &reference_;
    m.glassStats = glassStats_;
    m.reflectors = static_cast<uint32_t>(renderer_->reflectors().size());
    m.reflectorsProjected = std::min(m.reflectors, gpu::kPprMaxReflectors);
    const ShadowMapCache& shadowCache = renderer_->shadowMapCache();
    m.shadowMap = shadowMapSummary(settings_.values().view.shadowCache, shadowCache.animated(), shadowCache.counts().still,
                                   shadowCache.counts().moving);
    m.status = status_;
    const PanelActions a = drawPanel(m);
    status_ = m.status;
    const VkExtent2D extent = swapchain_->extent();
    EditorView view;
    view.size = glm::vec2(extent.width, extent.height);
    view.eye = camera_.pose.position;
    view.forward = scene::viewDirection(camera_.pose.yawDeg, camera_.pose.pitchDeg);
    view.viewProj = scene::projectionMatrix(camera_.pose.fovYDeg, view.size.x / std::max(view.size.y, 1.0f), scene::kNearPlane) *
                    scene::viewMatrix(camera_.pose);
    bool edited = editor_->draw(view, !imgui_->wantsMouse());
    for (EditorKey key : input_.editorKeys)
        if (!imgui_->wantsTextInput()) edited |= editor_->shortcut(key);
    input_.editorKeys.clear();
    if (edited) renderer_->setReflectors(document_->reflectors());
    glm::ivec2 pixel;
    if (const std::optional<ViewClick> click = editor_->takeClick(pixel)) {
        pendingClick_ = click;
        pickPixel_ = pixel;
    }
    imgui_->endFrame();

    if (a.jumpToCamera >= 0 && a.jumpToCamera < static_cast<int>(cameras_.size())) {
        cameraIndex_ = a.jumpToCamera;
        camera_.pose = cameras_[static_cast<size_t>(cameraIndex_)].pose;
        cameraName_ = cameras_[static_cast<size_t>(cameraIndex_)].name;
        cameraCut_ = true;  // a jump, not motion: TAA must not blend the old view into the new one
    }
    if (a.vsyncChanged) {
        vsync_ = m.vsync;
        swapchainDirty_ = true;
    }
    if (a.capture) captureRequested_ = true;
    if (!a.technique.empty()) technique_ = a.technique;
}

bool Viewer::renderFrame(uint32_t slot) {
    lastPresentMs_ = 0.0;
    VkDevice dev = ctx_.device();
    uint32_t imageIndex = 0;
    const VkResult acq = vkAcquireNextImageKHR(dev, swapchain_->handle(), UINT64_MAX, sync_.acquired[slot], VK_NULL_HANDLE, &imageIndex);
    if (acq == VK_ERROR_OUT_OF_DATE_KHR) {  // the semaphore was not signalled: nothing to undo
        swapchainDirty_ = true;
        return false;
    }
    if (acq == VK_SUBOPTIMAL_KHR) swapchainDirty_ = true;  // the semaphore is signalled: render and present this one
    else VK_CHECK(acq);

    VK_CHECK(vkResetFences(dev, 1, &sync_.fence[slot]));
    VkCommandBuffer cmd = sync_.cmd[slot];
    VK_CHECK(vkResetCommandBuffer(cmd, 0));
    VkCommandBufferBeginInfo bi{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    bi.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    VK_CHECK(vkBeginCommandBuffer(cmd, &bi));

    const VkExtent2D extent = swapchain_->extent();
    graph::ExternalImage target;
    target.image = swapchain_->image(imageIndex);
    target.view = swapchain_->view(imageIndex);
    target.desc = {extent.width, extent.height, swapchain_->format(), 1};
    // Contents are not kept (tonemap overwrites the whole image); the acquire semaphore is waited at
    // COLOR_ATTACHMENT_OUTPUT, so the first barrier chains to it from that stage.
    target.state = {VK_IMAGE_LAYOUT_UNDEFINED, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_2_NONE};
    target.finalAccess = graph::Access::Present;

    FrameRequest req;
    req.camera = camera_.pose;
    req.extent = scaledExtent(extent, renderScale_);  // the tonemap pass upscales it into the window's image
    req.target = &target;
    // Hold-to-compare: while B is held the frame shows the reference.
    const bool holdCompare = !imgui_->wantsKeyboard() && glfwGetKey(window_.handle, GLFW_KEY_B) == GLFW_PRESS;
    req.technique = holdCompare ? reference_ : technique_;
    req.reference = reference_;
    req.settings = settings_.values();
    req.cameraCut = std::exchange(cameraCut_, false);
    if (!scene_.animation.empty()) req.sceneTime = sceneClock_;
    if (pendingClick_) {  // the G-buffer under the click, read back once this slot's fence signals
        req.taps.push_back(pickTap_->tap(renderPixelOf(pickPixel_, extent, req.extent), &pickImport_[slot]));
        pickIssued_[slot] = true;
    }
    abTaps_->attach(req.taps, ab_, abSplit_);
    req.taps.push_back({TapPoint::AfterOutput, [this](TapContext& t) {
                            t.board.put(FinalColor{imgui_->addPass(t.graph, t.board.get<FinalColor>().image)});
                        }});
    const FrameRecord rec = renderer_->record(cmd, slot, req);
    if (!rec.cullLog.empty() && frames_ == 0) std::fprintf(stderr, "%s", rec.cullLog.c_str());
    warning_ = rec.warning;
    VK_CHECK(vkEndCommandBuffer(cmd));

    vk::submit(ctx_, cmd, sync_.fence[slot], sync_.acquired[slot], VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
               swapchain_->renderFinished(imageIndex));
    sync_.busy[slot] = true;

    VkSemaphore renderFinished = swapchain_->renderFinished(imageIndex);
    VkSwapchainKHR sc = swapchain_->handle();
    VkPresentInfoKHR pi{VK_STRUCTURE_TYPE_PRESENT_INFO_KHR};
    pi.waitSemaphoreCount = 1;
    pi.pWaitSemaphores = &renderFinished;
    pi.swapchainCount = 1;
    pi.pSwapchains = &sc;
    pi.pImageIndices = &imageIndex;
    // Timed apart from the CPU's work: with vsync it waits for the display, and lavapipe's present
    // waits for the frame itself, which its CPU threads are still rendering.
    const Clock::time_point presentStart = Clock::now();
    const VkResult pr = vkQueuePresentKHR(ctx_.queue(), &pi);
    lastPresentMs_ = std::chrono::duration<double, std::milli>(Clock::now() - presentStart).count();
    if (pr == VK_ERROR_OUT_OF_DATE_KHR || pr == VK_SUBOPTIMAL_KHR) swapchainDirty_ = true;
    else VK_CHECK(pr);
    return true;
}

void Viewer::saveCapture() {
    namespace fs = std::filesystem;
    try {
        vkDeviceWaitIdle(ctx_.device());
        // The capture re-uses the renderer's frame slots; the viewer's own timings there are stale now.
        for (bool& b : sync_.busy) b = false;
        if (!headless_) headless_ = std::make_unique<HeadlessRenderer>(ctx_, *renderer_);
        headless_->setTechnique(technique_);
        headless_->settings() = settings_;
        if (!scene_.animation.empty()) headless_->setSceneTime(sceneClock_);  // what the window shows
        const VkExtent2D extent = swapchain_->extent();
        const uint32_t errorsBefore = ctx_.validationErrors();
        CaptureResult r = headless_->capture(camera_.pose, extent, 3);
        fs::path dir;
        for (uint32_t n = 1;; ++n) {
            dir = fs::path(options_.out) / ("view-capture-" + std::to_string(n));
            if (!fs::exists(dir)) break;
        }
        fs::create_directories(dir);
        util::writePng((dir / "final.png").string(), r.image);
        ReportInfo info;
        info.scene = scene_.sourcePath;
        info.camera = cameraName_;
        info.pose = camera_.pose;
        info.size = extent;
        info.technique = technique_;
        info.reflectors = renderer_->reflectors().size();
        info.settings = &settings_;
        info.validationEnabled = ctx_.validationEnabled();
        info.validationErrors = ctx_.validationErrors() - errorsBefore;
        info.images = {{"final", "final.png"}};
        writeJsonFile((dir / "report.json").string(), makeReport(ctx_, info, r));
        status_ = "saved " + (dir / "final.png").string();
        std::printf("ppr: %s\n", status_.c_str());
    } catch (const std::exception& e) {
        status_ = std::string("capture failed: ") + e.what();
        std::fprintf(stderr, "ppr: %s\n", status_.c_str());
    }
}

void Viewer::run(uint64_t maxFrames, uint64_t captureAt) {
    GLFWwindow* w = window_.handle;
    Clock::time_point last = Clock::now();
    while (!glfwWindowShouldClose(w) && !g_quit) {
        if (maxFrames && frames_ >= maxFrames) break;
        glfwPollEvents();
        if (soak_ && soak_->advance(frames_, w, settings_, technique_, renderScale_))
            std::printf("%s\n", formatMemorySample(sampleMemory(ctx_, frames_)).c_str()), std::fflush(stdout);

        int fbw = 0, fbh = 0;
        glfwGetFramebufferSize(w, &fbw, &fbh);
        if (fbw == 0 || fbh == 0) {  // minimised: nothing to render into
            glfwWaitEventsTimeout(0.25);  // (a timeout so that a quit signal is still noticed)
            last = Clock::now();
            continue;
        }
        if (input_.resized || swapchainDirty_) {
            input_.resized = false;
            if (!recreateSwapchain()) continue;
        }

        const Clock::time_point now = Clock::now();
        const double dtMs = std::chrono::duration<double, std::milli>(now - last).count();
        last = now;

        const uint32_t slot = static_cast<uint32_t>(frames_ % Renderer::kFramesInFlight);
        VK_CHECK(vkWaitForFences(ctx_.device(), 1, &sync_.fence[slot], VK_TRUE, UINT64_MAX));
        if (sync_.busy[slot]) {
            timings_.add(renderer_->timings(slot));
            if (auto stats = renderer_->frameStats(slot)) pprStats_ = stats;
            glassStats_ = renderer_->glassStats(slot);
            if (pickIssued_[slot]) {
                pickIssued_[slot] = false;
                vmaInvalidateAllocation(ctx_.allocator(), pickBuffer_[slot].allocation, 0, VK_WHOLE_SIZE);
                gpu::PickResult pick;
                std::memcpy(&pick, pickBuffer_[slot].mapped, sizeof pick);
                if (pendingClick_ && editor_->applyPick(*pendingClick_, pick)) renderer_->setReflectors(document_->reflectors());
                pendingClick_.reset();
            }
            sync_.busy[slot] = false;
        }
        // Every frame at or before frames_ - kFramesInFlight has completed: unused transients can go.
        if (frames_ % 120 == 119) renderer_->executor().trimPool(Renderer::kFramesInFlight + 1);

        const Clock::time_point cpuStart = Clock::now();
        for (; input_.cycleDebug > 0; --input_.cycleDebug)
            if (!imgui_->wantsTextInput()) cycleDebugView(settings_);
        for (; input_.cycleTechnique > 0; --input_.cycleTechnique)
            if (!imgui_->wantsTextInput()) technique_ = nextTechnique(technique_);
        if (input_.capture) {
            input_.capture = false;
            if (!imgui_->wantsTextInput()) captureRequested_ = true;
        }
        updateCamera(static_cast<float>(dtMs * 1e-3));
        if (animate_) sceneClock_ += dtMs * 1e-3;
        buildUi();
        if (swapchainDirty_) continue;  // vsync toggled: recreate before rendering
        const bool presented = renderFrame(slot);
        const double cpuMs = std::chrono::duration<double, std::milli>(Clock::now() - cpuStart).count() - lastPresentMs_;
        if (!presented) continue;

        ++frames_;
        logMemoryEvery(ctx_, frames_);
        auto push = [](std::deque<double>& d, double v) {
            d.push_back(v);
            while (d.size() > TimingHistory::kFrames) d.pop_front();
        };
        if (frames_ > 1) push(frameMs_, dtMs);
        push(cpuMs_, cpuMs);
        push(presentMs_, lastPresentMs_);
        if (captureAt && frames_ == captureAt) captureRequested_ = true;
        if (captureRequested_) {
            captureRequested_ = false;
            saveCapture();
        }
    }
    vkDeviceWaitIdle(ctx_.device());
}

}  // namespace

int runViewer(const Options& o) {
    const uint64_t maxFrames = envCount("PPR_VIEWER_FRAMES");
    const uint64_t captureAt = envCount("PPR_VIEWER_SCREENSHOT_AT");
    const scene::Scene scene = loadScene(o);
    resolveCameras(scene, o.camera);  // a bad --camera fails before a window opens
    GlfwSession glfw;
    uint32_t extensionCount = 0;
    const char** extensions = glfwGetRequiredInstanceExtensions(&extensionCount);
    if (!extensions) throw std::runtime_error("view: GLFW cannot create Vulkan surfaces on this display");
    vk::ContextOptions co;
    co.validation = o.validation;
    co.instanceExtensions.assign(extensions, extensions + extensionCount);
    co.swapchain = true;
    std::unique_ptr<vk::Context> ctx = vk::Context::create(co);
    std::printf("ppr: %s (%s, Vulkan %s)%s\n", ctx->info().name.c_str(), ctx->info().type.c_str(), ctx->info().apiVersionString.c_str(),
                ctx->validationEnabled() ? ", validation + synchronization validation on" : "");
    {
        QuitSignals signals;
        Viewer viewer(o, *ctx, scene);
        viewer.run(maxFrames, captureAt);
    }
    if (ctx->validationErrors() > 0) {
        std::fprintf(stderr, "ppr: %u validation error(s)\n", ctx->validationErrors());
        return 1;
    }
    return 0;
}

}  // namespace ppr::app
