#include "viewer/viewer_ui.hpp"

#include "render/render_scale.hpp"
#include "settings/debug_views.hpp"

#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_vulkan.h>
#include <imgui.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace ppr::app {

// ---------------------------------------------------------------------------------------------------
// ImGui layer

namespace {
void checkImGuiVk(VkResult r) {
    if (r < 0) std::fprintf(stderr, "ppr: ImGui Vulkan backend: %s\n", vk::resultName(r));
}
}  // namespace

ImGuiLayer::ImGuiLayer(const vk::Context& ctx, GLFWwindow* window, passes::UiPass& ui, VkFormat format, uint32_t imageCount)
    : ctx_(ctx), ui_(ui) {
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    try {
        ImGuiIO& io = ImGui::GetIO();
        io.IniFilename = nullptr;  // no imgui.ini in the working directory
        ImGui::StyleColorsDark();
        ImGui::GetStyle().WindowRounding = 4.0f;
        // install_callbacks = true chains to the viewer's GLFW callbacks installed before this.
        if (!ImGui_ImplGlfw_InitForVulkan(window, true)) throw std::runtime_error("view: ImGui GLFW backend failed to initialise");
        glfwBackend_ = true;

        VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 16};
        VkDescriptorPoolCreateInfo pci{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
        pci.flags = VK_DESCRIPTOR_POOL_CREATE_FREE_DESCRIPTOR_SET_BIT;
        pci.maxSets = 16;
        pci.poolSizeCount = 1;
        pci.pPoolSizes = &size;
        VK_CHECK(vkCreateDescriptorPool(ctx.device(), &pci, nullptr, &pool_));
        ctx.name(pool_, VK_OBJECT_TYPE_DESCRIPTOR_POOL, "imgui descriptors");
        initVulkan(format, imageCount);
    } catch (...) {
        shutdownVulkan();
        if (glfwBackend_) ImGui_ImplGlfw_Shutdown();
        ImGui::DestroyContext();
        if (pool_) vkDestroyDescriptorPool(ctx.device(), pool_, nullptr);
        throw;
    }
}

ImGuiLayer::~ImGuiLayer() {
    vkDeviceWaitIdle(ctx_.device());
    shutdownVulkan();
    if (glfwBackend_) ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
    vkDestroyDescriptorPool(ctx_.device(), pool_, nullptr);
}

void ImGuiLayer::initVulkan(VkFormat format, uint32_t imageCount) {
    ImGui_ImplVulkan_InitInfo ii{};
    ii.Instance = ctx_.instance();
    ii.PhysicalDevice = ctx_.physicalDevice();
    ii.Device = ctx_.device();
    ii.QueueFamily = ctx_.queueFamily();
    ii.Queue = ctx_.queue();
    ii.DescriptorPool = pool_;
    ii.Subpass = 0;
    ii.MinImageCount = std::max(imageCount, 2u);
    // The backend cycles ImageCount vertex/index buffers without fences: it must exceed the frames
    // that can be in flight.
    ii.ImageCount = std::max({imageCount, ii.MinImageCount, Renderer::kFramesInFlight + 1});
    ii.MSAASamples = VK_SAMPLE_COUNT_1_BIT;
    ii.CheckVkResultFn = checkImGuiVk;
    if (!ImGui_ImplVulkan_Init(&ii, ui_.renderPass(format))) throw std::runtime_error("view: ImGui Vulkan backend failed to initialise");
    vulkanBackend_ = true;
    format_ = format;
    ctx_.immediateSubmit([](VkCommandBuffer cmd) {
        if (!ImGui_ImplVulkan_CreateFontsTexture(cmd)) throw std::runtime_error("view: ImGui font upload failed");
    });
    ImGui_ImplVulkan_DestroyFontUploadObjects();
}

void ImGuiLayer::shutdownVulkan() {
    if (!vulkanBackend_) return;
    ImGui_ImplVulkan_Shutdown();
    vulkanBackend_ = false;
}

void ImGuiLayer::swapchainChanged(VkFormat format, uint32_t imageCount) {
    if (format != format_) {
        // The backend's pipeline is tied to a render pass of the old format.
        shutdownVulkan();
        VK_CHECK(vkResetDescriptorPool(ctx_.device(), pool_, 0));
        initVulkan(format, imageCount);
    } else {
        ImGui_ImplVulkan_SetMinImageCount(std::max(imageCount, 2u));
    }
}

void ImGuiLayer::beginFrame() {
    ImGui_ImplVulkan_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
}

void ImGuiLayer::endFrame() { ImGui::Render(); }

graph::ImageHandle ImGuiLayer::addPass(graph::RenderGraph& g, graph::ImageHandle target) {
    return ui_.add(g, target, [](VkCommandBuffer cmd) {
        if (ImDrawData* data = ImGui::GetDrawData()) ImGui_ImplVulkan_RenderDrawData(data, cmd);
    });
}

bool ImGuiLayer::wantsMouse() const { return ImGui::GetIO().WantCaptureMouse; }
bool ImGuiLayer::wantsKeyboard() const { return ImGui::GetIO().WantCaptureKeyboard; }
bool ImGuiLayer::wantsTextInput() const { return ImGui::GetIO().WantTextInput; }

// ---------------------------------------------------------------------------------------------------
// Panel

std::string nextTechnique(const std::string& current) {
    const auto& list = techniqueNames();
    auto it = std::find(list.begin(), list.end(), current);
    return it == list.end() || it + 1 == list.end() ? list.front() : *(it + 1);
}

std::string cycleDebugView(Settings& settings) {
    const std::vector<DebugViewDecl>& views = debugViews();
    const uint32_t current = settings.values().view.debug;
    auto it = std::find_if(views.begin(), views.end(), [&](const DebugViewDecl& v) { return v.value == current; });
    const size_t next = it == views.end() ? 0 : (static_cast<size_t>(it - views.begin()) + 1) % views.size();
    settings.set("debug", views[next].name);
    return views[next].name;
}

namespace {

void helpTooltip(const std::string& help) {
    if (!help.empty() && ImGui::IsItemHovered()) ImGui::SetTooltip("%s", help.c_str());
}

// One widget per declared setting, by its kind; every change goes through Settings::set (the same
// validation as --set).
void settingWidget(const SettingDecl& decl, PanelModel& m) {
    Settings& settings = *m.settings;
    auto apply = [&](const std::string& value) {
        try {
            settings.set(decl.key, value);
        } catch (const std::exception& e) {
            m.status = e.what();
        }
    };
    const std::string current = settings.get(decl.key);
    const std::string help = decl.help + " [" + decl.owner + "; default " + decl.defaultValue + "]";
    switch (decl.kind) {
        case SettingKind::Toggle: {
            bool on = current == "1";
            if (ImGui::Checkbox(decl.key.c_str(), &on)) apply(on ? "1" : "0");
            break;
        }
        case SettingKind::Choice:
            if (ImGui::BeginCombo(decl.key.c_str(), current.c_str())) {
                for (const std::string& c : decl.choices) {
                    const bool selected = c == current;
                    if (ImGui::Selectable(c.c_str(), selected) && !selected) apply(c);
                    if (selected) ImGui::SetItemDefaultFocus();
                }
                ImGui::EndCombo();
            }
            break;
        case SettingKind::Integer: {
            ImGuiSliderFlags flags = ImGuiSliderFlags_AlwaysClamp;
            if (decl.min > 0.0 && decl.max / decl.min >= 100.0) flags |= ImGuiSliderFlags_Logarithmic;
            int v = static_cast<int>(std::lround(settings.number(decl.key)));
            if (ImGui::SliderInt(decl.key.c_str(), &v, static_cast<int>(decl.min), static_cast<int>(decl.max), "%d", flags))
                apply(std::to_string(std::clamp(v, static_cast<int>(decl.min), static_cast<int>(decl.max))));
            break;
        }
        case SettingKind::Number: {
            ImGuiSliderFlags flags = ImGuiSliderFlags_AlwaysClamp;
            if (decl.min > 0.0 && decl.max / decl.min >= 100.0) flags |= ImGuiSliderFlags_Logarithmic;
            float v = static_cast<float>(settings.number(decl.key));
            if (ImGui::SliderFloat(decl.key.c_str(), &v, static_cast<float>(decl.min), static_cast<float>(decl.max), "%.3g", flags)) {
                char text[32];
                std::snprintf(text, sizeof text, "%.6g", std::clamp(static_cast<double>(v), decl.min, decl.max));
                apply(text);
            }
            break;
        }
    }
    std::string tip = help;
    for (size_t i = 0; i < decl.choiceHelp.size(); ++i) tip += "\n" + decl.choices[i] + ": " + decl.choiceHelp[i];
    helpTooltip(decl.kind == SettingKind::Number || decl.kind == SettingKind::Integer ? tip + " (ctrl+click to type a value)" : tip);
}

}  // namespace

PanelActions drawPanel(PanelModel& m) {
    PanelActions a;
    const ImGuiIO& io = ImGui::GetIO();
    ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(330, std::clamp(io.DisplaySize.y - 16.0f, 120.0f, 580.0f)), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowBgAlpha(0.85f);
    if (!ImGui::Begin("ppr")) {
        ImGui::End();
        return a;
    }
    ImGui::PushItemWidth(170.0f);
    if (m.device) {
        ImGui::TextUnformatted(m.device->name.c_str());
        ImGui::Text("%s, Vulkan %s", m.device->type.c_str(), m.device->apiVersionString.c_str());
    }
    if (m.renderExtent.width == m.extent.width && m.renderExtent.height == m.extent.height)
        ImGui::Text("%u x %u", m.extent.width, m.extent.height);
    else
        ImGui::Text("%u x %u, rendered at %u x %u", m.extent.width, m.extent.height, m.renderExtent.width, m.renderExtent.height);
    ImGui::Text("frame %.2f ms (%.1f FPS)", m.frameMs, m.frameMs > 0.0 ? 1000.0 / m.frameMs : 0.0);
    ImGui::Text("CPU %.2f ms (UI, record, submit)", m.cpuMs);
    // Lavapipe's present waits until its CPU threads have rendered the frame; a GPU's, with vsync, for the display.
    const bool cpuDevice = m.device && m.device->type == "cpu";
    ImGui::Text("present %.2f ms%s", m.presentMs, cpuDevice ? " (waits for the frame)" : m.vsync ? " (waits for vsync)" : "");
    ImGui::TextDisabled("F2: debug view  F3: technique  F12: capture");
    ImGui::TextDisabled("WASD move, Q/E down/up");
    ImGui::TextDisabled("right mouse: look, wheel: speed");

    if (ImGui::CollapsingHeader("View", ImGuiTreeNodeFlags_DefaultOpen)) {
        if (m.cameras && !m.cameras->empty()) {
            const char* preview = m.cameraIndex >= 0 ? (*m.cameras)[static_cast<size_t>(m.cameraIndex)].name.c_str() : "(free)";
            if (ImGui::BeginCombo("camera", preview)) {
                for (size_t i = 0; i < m.cameras->size(); ++i) {
                    const bool selected = static_cast<int>(i) == m.cameraIndex;
                    if (ImGui::Selectable((*m.cameras)[i].name.c_str(), selected)) a.jumpToCamera = static_cast<int>(i);
                }
                ImGui::EndCombo();
            }
        }
        ImGui::Text("camera speed %.2f m/s", m.cameraSpeed);
        if (ImGui::Checkbox("vsync", &m.vsync)) a.vsyncChanged = true;
        if (m.renderScale) {
            char current[16];
            std::snprintf(current, sizeof current, "%.2f", *m.renderScale);
            if (ImGui::BeginCombo("render scale", current)) {
                for (float s : kRenderScaleChoices) {
                    char label[16];
                    std::snprintf(label, sizeof label, "%.2f", s);
                    if (ImGui::Selectable(label, s == *m.renderScale)) *m.renderScale = s;
                }
                ImGui::EndCombo();
            }
            helpTooltip("the frame is rendered at this fraction of the window's size and upscaled (bilinear) into it; "
                        "below 1 a CPU device stays interactive (--render-scale S takes any value in 0.1..1)");
        }
        if (m.animate) {
            ImGui::Checkbox("animate", m.animate);
            ImGui::SameLine();
            ImGui::Text("scene %.2f s", m.sceneSeconds);
        }
    }

    if (ImGui::CollapsingHeader("Technique", ImGuiTreeNodeFlags_DefaultOpen)) {
        if (ImGui::BeginCombo("technique", m.technique.c_str())) {
            for (const std::string& t : techniqueNames())
                if (ImGui::Selectable(t.c_str(), t == m.technique)) a.technique = t;
            ImGui::EndCombo();
        }
        if (m.reference && ImGui::BeginCombo("reference", m.reference->c_str())) {
            for (const TechniqueDesc& t : techniqueTable())
                if (t.reference && ImGui::Selectable(t.name.c_str(), t.name == *m.reference)) *m.reference = t.name;
            ImGui::EndCombo();
        }
        helpTooltip("the ground truth A/B, the heat map and hold-B show: planar (mirrored re-render, flat mirrors) or "
                    "raytraced (ray queries: normal maps, glass, off-screen reflections)");
        if (m.ab && m.abSplit && m.reference) {
            // A/B: the reference beside the technique, or the technique's error against it.
            const std::string split = "split (" + *m.reference + " on the right)";
            const char* modes[] = {"off", split.c_str(), "error heat map"};
            int mode = static_cast<int>(*m.ab);
            if (ImGui::Combo("A/B", &mode, modes, 3)) *m.ab = static_cast<AbView>(mode);
            if (*m.ab == AbView::Split) ImGui::SliderFloat("split", m.abSplit, 0.0f, 1.0f, "%.2f");
            ImGui::TextDisabled("hold B: show the reference");
        }
        if (!m.warning.empty()) ImGui::TextColored(ImVec4(1.0f, 0.6f, 0.2f, 1.0f), "%s", m.warning.c_str());
        if (m.technique == "ppr" && m.pprStats) {
            // The counts behind tiles / indirect: what the classification found and what culling kept.
            const gpu::PprFrameStats& s = *m.pprStats;
            const uint32_t tiles = gpu::pprTilesCovering(m.renderExtent.width) * gpu::pprTilesCovering(m.renderExtent.height);  // the frame's tiles
            ImGui::Text("reflectors %u (PPR projects %u; on screen %u, reflecting %u)", m.reflectors, m.reflectorsProjected,
                        s.reflectorsOnScreen, s.reflectorsReflecting);
            ImGui::Text("tiles %u: reflective %u, other reflective %u", tiles, s.dispatch[gpu::kTileClassPlanar].x,
                        s.dispatch[gpu::kTileClassOther].x);
            ImGui::Text("reflector-tile pairs %u of %llu (max %u per tile)", s.reflectorTilePairs,
                        static_cast<unsigned long long>(s.tilesWithContent) * m.reflectorsProjected, s.maxTileSurvivors);
        }
        if (m.technique == "ppr" && m.glassStats) {
            const GlassStats& g = *m.glassStats;
            ImGui::Text("glass atlas %ux%u: %u of %u panels, scale %.2f", g.atlasSize, g.atlasSize, g.regions(), g.visible, g.scale);
            if (g.overflowed()) ImGui::TextColored(ImVec4(1.0f, 0.6f, 0.2f, 1.0f), "%s", g.overflowMessage().c_str());
        }
    }

    if (ImGui::CollapsingHeader("Settings", ImGuiTreeNodeFlags_DefaultOpen)) {
        for (const SettingDecl& decl : settingDecls()) settingWidget(decl, m);
    }

    if (ImGui::CollapsingHeader("GPU passes", ImGuiTreeNodeFlags_DefaultOpen) && m.timings) {
        ImGui::TextDisabled("median of the last %zu frames", TimingHistory::kFrames);
        if (ImGui::BeginTable("passes", 3, ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV)) {
            ImGui::TableSetupColumn("pass", ImGuiTableColumnFlags_WidthFixed, 90.0f);
            ImGui::TableSetupColumn("ms", ImGuiTableColumnFlags_WidthFixed, 56.0f);
            ImGui::TableSetupColumn("history", ImGuiTableColumnFlags_WidthStretch);
            ImGui::TableHeadersRow();
            for (const TimingHistory::Row& r : m.timings->rows()) {
                ImGui::TableNextRow();
                ImGui::TableNextColumn();
                ImGui::TextUnformatted(r.name.c_str());
                ImGui::TableNextColumn();
                ImGui::Text("%7.3f", r.medianMs);
                ImGui::TableNextColumn();
                const std::string id = "##" + r.name;
                ImGui::PlotLines(id.c_str(), r.history.data(), static_cast<int>(r.history.size()), 0, nullptr, 0.0f, FLT_MAX,
                                 ImVec2(std::max(ImGui::GetContentRegionAvail().x, 40.0f), 16.0f));
            }
            ImGui::EndTable();
        }
        ImGui::Text("total GPU %.3f ms", m.timings->totalMedianMs());
        if (!m.shadowMap.empty()) ImGui::TextDisabled("%s", m.shadowMap.c_str());
    }

    if (ImGui::Button("Save capture (F12)")) a.capture = true;
    if (!m.status.empty()) ImGui::TextWrapped("%s", m.status.c_str());
    ImGui::PopItemWidth();
    ImGui::End();
    return a;
}

}  // namespace ppr::app
