#pragma once
// The reflector editor in the viewer: the "Reflectors" ImGui window (list, fields with drag widgets,
// add / duplicate / delete / undo / redo / save / reload / auto-fit), the selection outline and the
// on-screen handles (centre: move in the plane; edge squares: resize with the opposite edge fixed;
// ring: rotate about the normal), and clicks in the view (pick, Ctrl: snap a new reflector onto the
// surface, Alt: auto-fit the planar region under the cursor). The document model is
// reflector_editor.hpp; the pick comes from the G-buffer (passes/pick).
#include "pick/pick.h"
#include "editor/reflector_editor.hpp"
#include "scene/scene.hpp"

#include <glm/glm.hpp>

#include <optional>
#include <string>

namespace ppr::app {

// A click in the view waiting for the G-buffer under it (the pick arrives a frame or two later).
enum class ViewClick { Select, Snap, AutoFit };
// Keyboard shortcuts, delivered as key events (a press and release within one frame still counts).
enum class EditorKey { Undo, Redo, Save, Duplicate, Delete };

struct EditorView {
    glm::mat4 viewProj{1.0f};
    glm::vec3 eye{0.0f};
    glm::vec3 forward{0.0f, 0.0f, -1.0f};  // view direction (unit)
    glm::vec2 size{0.0f};                  // pixels
};

class ReflectorEditorUi {
public:
    ReflectorEditorUi(ReflectorDocument& document, const scene::Scene& scene) : doc_(document), scene_(scene) {}

    // The window, the outline and the handles. Returns true when the reflector list changed (give it
    // to the renderer).
    bool draw(const EditorView& view, bool mouseFree);
    // Ctrl+Z / Ctrl+Y (Ctrl+Shift+Z) / Ctrl+S / Ctrl+D / Delete; returns true when the list changed.
    bool shortcut(EditorKey key);
    // A left click in the view (not on a handle): what to do once the pick for `pixel` arrives.
    std::optional<ViewClick> takeClick(glm::ivec2& pixel);
    // The pick for the pending click arrived; returns true when the list changed.
    bool applyPick(ViewClick click, const gpu::PickResult& pick);

    const std::string& message() const { return message_; }

private:
    bool drawWindow(const EditorView& view);
    bool drawFields(std::size_t index);
    bool drawHandles(const EditorView& view, bool mouseFree);
    void report(const std::string& error, const std::string& success);

    ReflectorDocument& doc_;
    const scene::Scene& scene_;
    std::string message_;
    std::optional<ViewClick> pendingClick_;
    glm::ivec2 pendingPixel_{0};
    int activeHandle_ = -1;  // 0 centre, 1..4 edges, 5 ring; -1 none
    scene::Reflector dragStart_;  // the reflector when the handle was grabbed
    glm::vec3 dragAnchor_{0.0f};  // where the mouse ray met its plane then
    float ringStartAngle_ = 0.0f;
    float rotateDrag_ = 0.0f;     // degrees the "rotate" field was dragged since the press (applied as deltas)
    char saveAsPath_[512] = {};
};

}  // namespace ppr::app
