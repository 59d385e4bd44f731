#pragma once
// The reflector editor's document model: the list being edited, selection, undo/redo, the unsaved
// mark, snap-to-surface creation, save/load, and the pure math behind the on-screen handles.
// No Vulkan and no ImGui here, so all of it is unit-tested (tests/unit/editor).
#include "scene/reflector.hpp"

#include <glm/glm.hpp>

#include <cstddef>
#include <cstdint>
#include <deque>
#include <optional>
#include <string>
#include <vector>

namespace ppr::app {

// Exact (bitwise-value) equality: undo must restore states exactly, so no tolerance here.
bool sameReflector(const scene::Reflector& a, const scene::Reflector& b);
bool sameReflectors(const std::vector<scene::Reflector>& a, const std::vector<scene::Reflector>& b);

// Names used by the editor. Both return a name not used by any reflector in `existing`.
// uniqueSnapName("puddle") -> "puddle_1", "puddle_2", ... (empty hint -> "reflector").
std::string uniqueSnapName(const std::string& hint, const std::vector<scene::Reflector>& existing);
// uniqueCopyName("floor") -> "floor_2", "floor_3", ...; uniqueCopyName("puddle_1") -> "puddle_2", ...
std::string uniqueCopyName(const std::string& name, const std::vector<scene::Reflector>& existing);

// Handle math (pure; the UI applies the result with ReflectorDocument::replace).
enum ReflectorEdge : int { kEdgePlusU = 0, kEdgeMinusU = 1, kEdgePlusV = 2, kEdgeMinusV = 3 };
constexpr float kMinEditHalfExtent = 0.005f;  // resize handles stop at 1 cm wide: never degenerate or flip

// Moves the centre by `delta` minus its normal component, so the reflector stays in its plane.
scene::Reflector moveAlongPlane(const scene::Reflector& r, const glm::vec3& delta);
// Moves one edge outward along its own direction by `amount` metres (negative shrinks) while the
// opposite edge stays fixed: the half extent changes by amount/2 and the centre shifts by amount/2.
// The width is clamped at 2 * kMinEditHalfExtent. An edge outside 0..3 returns `r` unchanged.
scene::Reflector resizeEdge(const scene::Reflector& r, int edge, float amount);
// Same, with the dragged edge placed at the projection of `point` onto the edge's axis.
scene::Reflector resizeEdgeTo(const scene::Reflector& r, int edge, const glm::vec3& point);
// Rotates the tangent in the plane about the normal (right-handed: +radians turns tangent towards
// the bitangent). The result is re-orthonormalised so repeated small rotations do not drift.
scene::Reflector rotateAboutNormal(const scene::Reflector& r, float radians);
// A reflector lying on the surface at `point` with the editor's defaults (see snapCreate), or an
// error ("" on success) for a non-finite point/normal or a zero normal.
std::string makeSnappedReflector(const glm::vec3& point, const glm::vec3& normal, scene::Reflector& out);

struct CreateResult {
    std::optional<std::size_t> index;  // the new reflector's index on success
    std::string error;                 // one line on failure; the document is unchanged
    explicit operator bool() const { return index.has_value(); }
};

class ReflectorDocument {
public:
    static constexpr std::size_t kMaxHistory = 256;     // undo steps kept; the oldest are dropped
    static constexpr float kDuplicateOffset = 0.25f;    // metres along the tangent, so the copy is visible
    static constexpr float kSnapHalfExtent = 0.5f;
    static constexpr float kSnapReflectance = 0.7f;

    // Starts clean (not dirty): e.g. the scene's reflectors and the file they came from ("" if none).
    explicit ReflectorDocument(std::vector<scene::Reflector> reflectors = {}, std::string path = {});

    const std::vector<scene::Reflector>& reflectors() const { return cur_.reflectors; }
    std::size_t size() const { return cur_.reflectors.size(); }
    const scene::Reflector& at(std::size_t i) const { return cur_.reflectors.at(i); }
    const std::string& path() const { return path_; }

    // Selection is view state, not an edit: changing it records no undo step. Undo/redo restore the
    // selection that went with the restored state.
    std::optional<std::size_t> selection() const { return cur_.selection; }
    void select(std::optional<std::size_t> index);  // out of range -> none

    // Edits: each records one undo step and clears redo. Indices out of range -> false / nullopt and
    // no change. An edit that changes nothing (replace with an identical value) records nothing.
    std::size_t add(scene::Reflector r);  // appends and selects; a clashing name is made unique
    std::optional<std::size_t> duplicate(std::size_t index);  // copy selected, offset, unique name
    bool remove(std::size_t index);
    bool replace(std::size_t index, const scene::Reflector& r);  // any field change
    void setAll(std::vector<scene::Reflector> reflectors);        // e.g. auto-fit all
    // Snap-to-surface creation (centre = point, unit normal, stable tangent, 0.5 x 0.5 m, opaque,
    // reflectance 0.7, name "<hint>_N"); selects it.
    CreateResult snapCreate(const glm::vec3& point, const glm::vec3& normal, const std::string& nameHint);

    // Continuous edits (dragging a handle): beginEdit, replace any number of times, endEdit -> one
    // undo step (none if the drag ended where it started). Any other edit, undo, redo, save or load
    // ends the drag first.
    bool beginEdit(std::size_t index);
    void endEdit();
    bool editing() const { return drag_.has_value(); }

    bool canUndo() const { return !undo_.empty() || dragChanged(); }
    bool canRedo() const { return !redo_.empty() && !editing(); }
    bool undo();
    bool redo();
    std::size_t undoDepth() const { return undo_.size(); }

    // Unsaved changes: compares the current state's version with the saved one, so undoing back to
    // the saved state is clean again.
    bool dirty() const { return cur_.version != savedVersion_; }

    // First problem that would stop a save, as "reflector <i> '<name>': <field>: <problem>"
    // (i is the 0-based list index), or "" when every reflector is valid and names are unique.
    std::string validate() const;
    // Save to path() / to `path` (which becomes path() on success). Return "" or a one-line error:
    // validate()'s message for an invalid document, else the I/O error naming the file. On error
    // nothing on disk changes (temp file + rename) and the document stays dirty.
    std::string save();
    std::string saveAs(const std::string& path);
    // Replaces the document with the file's reflectors (clears history and selection). On error the
    // document is unchanged and the message names the file.
    std::string load(const std::string& path);

private:
    struct State {
        std::vector<scene::Reflector> reflectors;
        std::optional<std::size_t> selection;
        std::uint64_t version = 0;  // unique per distinct state ever made; never reused
    };
    struct Drag {
        State before;
        bool changed = false;
    };

    void commitDrag();
    // Records `before` as one step and clears redo; cur_ gets a new version unless it already has one.
    void pushUndo(State before, bool freshVersion = true);
    bool dragChanged() const { return drag_ && drag_->changed; }

    State cur_;
    std::deque<State> undo_;
    std::vector<State> redo_;
    std::optional<Drag> drag_;
    std::uint64_t nextVersion_ = 1;
    std::uint64_t savedVersion_ = 0;
    std::string path_;
};

}  // namespace ppr::app
