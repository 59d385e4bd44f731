#include "editor/editor_ui.hpp"

#include "scene/reflector_fit.hpp"

#include <imgui.h>

#include <glm/gtc/constants.hpp>

#include <cmath>
#include <cstdio>
#include <cstring>

namespace ppr::app {
namespace {

constexpr float kHandleRadius = 7.0f;  // pixels
constexpr float kRingScale = 1.15f;    // ring radius / the larger half extent
constexpr int kRingSegments = 48;
constexpr ImU32 kOutline = IM_COL32(255, 200, 40, 255);
constexpr ImU32 kHandle = IM_COL32(255, 255, 255, 255);
constexpr ImU32 kActiveHandle = IM_COL32(255, 110, 0, 255);  // the handle being dragged (the UI test looks for it)

bool toScreen(const EditorView& v, const glm::vec3& p, ImVec2& out) {
    const glm::vec4 clip = v.viewProj * glm::vec4(p, 1.0f);
    if (clip.w <= 1e-4f) return false;
    const glm::vec2 px = (glm::vec2(clip) / clip.w * 0.5f + 0.5f) * v.size;
    out = ImVec2(px.x, px.y);
    return true;
}

// Where the mouse ray meets the plane through `point` with `normal`.
std::optional<glm::vec3> mouseOnPlane(const EditorView& v, const glm::vec3& point, const glm::vec3& normal) {
    const ImVec2 m = ImGui::GetMousePos();
    const glm::vec2 ndc = glm::vec2(m.x, m.y) / v.size * 2.0f - 1.0f;
    const glm::mat4 inv = glm::inverse(v.viewProj);
    glm::vec4 a = inv * glm::vec4(ndc, 1.0f, 1.0f), b = inv * glm::vec4(ndc, 0.5f, 1.0f);  // reverse-Z: 1 = near
    const glm::vec3 from = glm::vec3(a) / a.w, dir = glm::vec3(b) / b.w - from;
    const float denom = glm::dot(dir, normal);
    if (std::abs(denom) < 1e-8f) return std::nullopt;
    const float t = glm::dot(point - from, normal) / denom;
    if (t <= 0.0f) return std::nullopt;
    return from + dir * t;
}

float distanceToSegment(ImVec2 p, ImVec2 a, ImVec2 b) {
    const glm::vec2 pa(p.x - a.x, p.y - a.y), ba(b.x - a.x, b.y - a.y);
    const float h = glm::clamp(glm::dot(pa, ba) / std::max(glm::dot(ba, ba), 1e-6f), 0.0f, 1.0f);
    return glm::length(pa - ba * h);
}

// A reflector with a new normal: the tangent is re-orthogonalised against it (or replaced when parallel).
scene::Reflector withNormal(scene::Reflector r, glm::vec3 n) {
    if (!(glm::length(n) > 1e-6f)) return r;
    n = glm::normalize(n);
    glm::vec3 t = r.tangent - n * glm::dot(n, r.tangent);
    if (glm::length(t) < 1e-4f) t = std::abs(n.x) < 0.9f ? glm::vec3(1, 0, 0) - n * n.x : glm::vec3(0, 0, 1) - n * n.z;
    r.normal = n;
    r.tangent = glm::normalize(t);
    return r;
}

}  // namespace

void ReflectorEditorUi::report(const std::string& error, const std::string& success) { message_ = error.empty() ? success : error; }

bool ReflectorEditorUi::draw(const EditorView& view, bool mouseFree) {
    bool changed = drawWindow(view);
    changed |= drawHandles(view, mouseFree);
    return changed;
}

bool ReflectorEditorUi::shortcut(EditorKey key) {
    switch (key) {
    case EditorKey::Undo: return doc_.undo();
    case EditorKey::Redo: return doc_.redo();
    case EditorKey::Save: report(doc_.save(), "saved " + doc_.path()); return false;
    case EditorKey::Duplicate: return doc_.selection() && doc_.duplicate(*doc_.selection()).has_value();
    case EditorKey::Delete: return doc_.selection() && doc_.remove(*doc_.selection());
    }
    return false;
}

bool ReflectorEditorUi::drawWindow(const EditorView& view) {
    bool changed = false;
    ImGui::SetNextWindowPos(ImVec2(ImGui::GetIO().DisplaySize.x - 368, 8), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(360, 520), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowCollapsed(true, ImGuiCond_FirstUseEver);  // the view stays clickable until opened
    if (!ImGui::Begin("Reflectors")) {
        ImGui::End();
        return false;
    }
    ImGui::Text("%s%s", doc_.path().empty() ? "(no file)" : doc_.path().c_str(), doc_.dirty() ? " *" : "");
    if (ImGui::Button("Add")) {  // 3 m ahead, facing the camera (Ctrl+click snaps one onto a surface instead)
        const CreateResult created = doc_.snapCreate(view.eye + 3.0f * view.forward, -view.forward, "reflector");
        report(created.error, created ? "added " + doc_.at(*created.index).name : "");
        changed |= bool(created);
    }
    ImGui::SameLine();
    ImGui::BeginDisabled(!doc_.canUndo());
    if (ImGui::Button("Undo")) changed |= doc_.undo();
    ImGui::EndDisabled();
    ImGui::SameLine();
    ImGui::BeginDisabled(!doc_.canRedo());
    if (ImGui::Button("Redo")) changed |= doc_.redo();
    ImGui::EndDisabled();
    ImGui::SameLine();
    ImGui::BeginDisabled(!doc_.selection());
    if (ImGui::Button("Duplicate")) changed |= doc_.duplicate(*doc_.selection()).has_value();
    ImGui::SameLine();
    if (ImGui::Button("Delete")) changed |= doc_.remove(*doc_.selection());
    ImGui::EndDisabled();
    if (ImGui::Button("Save")) report(doc_.save(), "saved " + doc_.path());
    ImGui::SameLine();
    if (ImGui::Button("Reload") && !doc_.path().empty()) {
        const std::string error = doc_.load(doc_.path());
        report(error, "reloaded " + doc_.path());
        changed |= error.empty();
    }
    ImGui::SameLine();
    if (ImGui::Button("Auto-fit all")) {
        // Every mesh whose material is flagged reflective and is planar gets a fitted rectangle.
        std::vector<scene::Reflector> fitted = scene::autoFitAll(scene_);
        message_ = "auto-fit: " + std::to_string(fitted.size()) + " reflectors from the reflective meshes";
        doc_.setAll(std::move(fitted));
        changed = true;
    }
    ImGui::InputText("##saveas", saveAsPath_, sizeof saveAsPath_);
    ImGui::SameLine();
    if (ImGui::Button("Save as") && saveAsPath_[0]) report(doc_.saveAs(saveAsPath_), std::string("saved ") + saveAsPath_);
    ImGui::TextDisabled("click: select  Ctrl+click: snap a new one  Alt+click: auto-fit");
    if (!message_.empty()) ImGui::TextWrapped("%s", message_.c_str());
    ImGui::Separator();
    if (ImGui::BeginListBox("##list", ImVec2(-1, 150))) {
        for (std::size_t i = 0; i < doc_.size(); ++i) {
            const scene::Reflector& r = doc_.at(i);
            char label[160];
            std::snprintf(label, sizeof label, "%s  %s  %.2f##%zu", r.name.c_str(), r.kind == scene::ReflectorKind::Glass ? "glass" : "opaque",
                          r.reflectance, i);
            if (ImGui::Selectable(label, doc_.selection() == i)) doc_.select(i);
        }
        ImGui::EndListBox();
    }
    if (doc_.selection()) changed |= drawFields(*doc_.selection());
    ImGui::End();
    return changed;
}

bool ReflectorEditorUi::drawFields(std::size_t index) {
    scene::Reflector r = doc_.at(index);
    bool edited = false;
    // A drag widget is one undo step from press to release.
    auto track = [&](bool changedNow) {
        if (ImGui::IsItemActivated()) doc_.beginEdit(index);
        edited |= changedNow;
        if (ImGui::IsItemDeactivated()) doc_.endEdit();
    };
    char name[128];
    std::snprintf(name, sizeof name, "%s", r.name.c_str());
    if (ImGui::InputText("name", name, sizeof name, ImGuiInputTextFlags_EnterReturnsTrue)) {
        r.name = name;
        edited = true;
    }
    track(ImGui::DragFloat3("centre", &r.center.x, 0.01f));
    glm::vec3 n = r.normal;
    const bool normalChanged = ImGui::DragFloat3("normal", &n.x, 0.01f, -1.0f, 1.0f);
    track(normalChanged);
    if (normalChanged) r = withNormal(r, n);
    const float before = rotateDrag_;
    const bool rotated = ImGui::DragFloat("rotate (deg)", &rotateDrag_, 0.5f);
    track(rotated);
    if (rotated) r = rotateAboutNormal(r, glm::radians(rotateDrag_ - before));
    if (!ImGui::IsItemActive()) rotateDrag_ = 0.0f;
    track(ImGui::DragFloat2("half extents", &r.halfExtents.x, 0.01f, kMinEditHalfExtent, 100.0f));
    int kind = r.kind == scene::ReflectorKind::Glass ? 1 : 0;
    const char* kinds[] = {"opaque", "glass"};
    if (ImGui::Combo("kind", &kind, kinds, 2)) {
        r.kind = kind ? scene::ReflectorKind::Glass : scene::ReflectorKind::Opaque;
        edited = true;
    }
    track(ImGui::SliderFloat("reflectance", &r.reflectance, 0.0f, 1.0f));
    return edited && doc_.replace(index, r);
}

bool ReflectorEditorUi::drawHandles(const EditorView& view, bool mouseFree) {
    ImDrawList* draw = ImGui::GetForegroundDrawList();
    const std::optional<std::size_t> sel = doc_.selection();
    bool changed = false;
    const bool pressed = mouseFree && ImGui::IsMouseClicked(ImGuiMouseButton_Left);
    bool onHandle = false;
    if (sel) {
        const scene::Reflector& r = doc_.at(*sel);
        const glm::vec3 t = r.tangent * r.halfExtents.x, b = r.bitangent() * r.halfExtents.y;
        // Outline.
        ImVec2 corners[4];
        bool visible = toScreen(view, r.center - t - b, corners[0]) && toScreen(view, r.center + t - b, corners[1]) &&
                       toScreen(view, r.center + t + b, corners[2]) && toScreen(view, r.center - t + b, corners[3]);
        if (visible) draw->AddPolyline(corners, 4, kOutline, ImDrawFlags_Closed, 2.0f);
        // Handles: 0 centre, 1..4 edges (+u, −u, +v, −v), 5 the rotation ring.
        const glm::vec3 points[5] = {r.center, r.center + t, r.center - t, r.center + b, r.center - b};
        ImVec2 screen[5];
        bool on[5];
        for (int i = 0; i < 5; ++i) {
            on[i] = toScreen(view, points[i], screen[i]);
            if (!on[i]) continue;
            const ImU32 colour = i == activeHandle_ ? kActiveHandle : kHandle;
            if (i == 0) draw->AddCircleFilled(screen[i], kHandleRadius, colour);
            else draw->AddRectFilled(ImVec2(screen[i].x - 5, screen[i].y - 5), ImVec2(screen[i].x + 5, screen[i].y + 5), colour);
        }
        const float ringRadius = kRingScale * std::max(r.halfExtents.x, r.halfExtents.y);
        ImVec2 ring[kRingSegments];
        bool ringOn = true;
        for (int i = 0; i < kRingSegments; ++i) {
            const float a = 2.0f * glm::pi<float>() * float(i) / kRingSegments;
            ringOn &= toScreen(view, r.center + (r.tangent * std::cos(a) + r.bitangent() * std::sin(a)) * ringRadius, ring[i]);
        }
        if (ringOn) draw->AddPolyline(ring, kRingSegments, IM_COL32(120, 200, 255, 200), ImDrawFlags_Closed, 1.5f);

        const ImVec2 mouse = ImGui::GetMousePos();
        if (pressed) {
            for (int i = 0; i < 5 && activeHandle_ < 0; ++i)
                if (on[i] && std::hypot(mouse.x - screen[i].x, mouse.y - screen[i].y) <= kHandleRadius + 2.0f) activeHandle_ = i;
            if (activeHandle_ < 0 && ringOn)
                for (int i = 0; i < kRingSegments && activeHandle_ < 0; ++i)
                    if (distanceToSegment(mouse, ring[i], ring[(i + 1) % kRingSegments]) < 5.0f) activeHandle_ = 5;
            if (activeHandle_ >= 0) {
                onHandle = true;
                doc_.beginEdit(*sel);
                dragStart_ = r;
                const std::optional<glm::vec3> p = mouseOnPlane(view, r.center, r.normal);
                dragAnchor_ = p.value_or(r.center);
                const glm::vec3 d = dragAnchor_ - r.center;
                ringStartAngle_ = std::atan2(glm::dot(d, r.bitangent()), glm::dot(d, r.tangent));
            }
        }
        if (activeHandle_ >= 0 && ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
            const scene::Reflector& s = dragStart_;
            if (const std::optional<glm::vec3> p = mouseOnPlane(view, s.center, s.normal)) {
                scene::Reflector next = s;
                if (activeHandle_ == 0) next = moveAlongPlane(s, *p - dragAnchor_);
                else if (activeHandle_ <= 4) next = resizeEdgeTo(s, activeHandle_ - 1, *p);
                else {
                    const glm::vec3 d = *p - s.center;
                    next = rotateAboutNormal(s, std::atan2(glm::dot(d, s.bitangent()), glm::dot(d, s.tangent)) - ringStartAngle_);
                }
                changed |= doc_.replace(*sel, next);
            }
        }
    }
    if (activeHandle_ >= 0 && !ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
        doc_.endEdit();
        activeHandle_ = -1;
    }
    // A click elsewhere in the view: select / snap / auto-fit once the pick under it arrives.
    if (pressed && !onHandle && activeHandle_ < 0) {
        const ImGuiIO& io = ImGui::GetIO();
        pendingClick_ = io.KeyCtrl ? ViewClick::Snap : (io.KeyAlt ? ViewClick::AutoFit : ViewClick::Select);
        pendingPixel_ = glm::ivec2(int(io.MousePos.x), int(io.MousePos.y));
    }
    return changed;
}

std::optional<ViewClick> ReflectorEditorUi::takeClick(glm::ivec2& pixel) {
    if (!pendingClick_) return std::nullopt;
    pixel = pendingPixel_;
    std::optional<ViewClick> c = pendingClick_;
    pendingClick_.reset();
    return c;
}

bool ReflectorEditorUi::applyPick(ViewClick click, const gpu::PickResult& pick) {
    const bool surface = pick.position.w > 0.5f;
    switch (click) {
    case ViewClick::Select:
        doc_.select(pick.reflectorId != 0u ? std::optional<std::size_t>(pick.reflectorId - 1u) : std::nullopt);
        return false;
    case ViewClick::Snap: {
        if (!surface) {
            message_ = "snap: no surface under the cursor";
            return false;
        }
        const CreateResult created = doc_.snapCreate(glm::vec3(pick.position), glm::vec3(pick.normal), "puddle");
        report(created.error, created ? "snapped " + doc_.at(*created.index).name : "");
        return bool(created);
    }
    case ViewClick::AutoFit: {
        if (!surface) {
            message_ = "auto-fit: no surface under the cursor";
            return false;
        }
        std::optional<scene::Reflector> fitted = scene::fitPlanarRegion(scene_, glm::vec3(pick.position), glm::vec3(pick.normal));
        if (!fitted) {
            message_ = "auto-fit: the surface under the cursor is not planar";
            return false;
        }
        fitted->name = uniqueSnapName("fitted", doc_.reflectors());
        fitted->reflectance = ReflectorDocument::kSnapReflectance;
        doc_.add(*fitted);
        message_ = "auto-fit: " + fitted->name;
        return true;
    }
    }
    return false;
}

}  // namespace ppr::app
