// The reflector editor's document model and handle math (see reflector_editor.hpp).
#include "editor/reflector_editor.hpp"

#include <algorithm>
#include <cmath>
#include <exception>
#include <map>
#include <utility>

namespace ppr::app {

using scene::Reflector;

namespace {

bool finite3(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

bool nameUsed(const std::string& name, const std::vector<Reflector>& existing) {
    return std::any_of(existing.begin(), existing.end(), [&](const Reflector& r) { return r.name == name; });
}

// First free "<base>_<k>" for k = first, first+1, ... (always terminates: finitely many names exist).
std::string firstFree(const std::string& base, unsigned long long first, const std::vector<Reflector>& existing) {
    for (unsigned long long k = first;; ++k) {
        std::string candidate = base + "_" + std::to_string(k);
        if (!nameUsed(candidate, existing)) return candidate;
    }
}

// Unit direction of an edge's outward normal in the plane, and which half extent it controls.
bool edgeAxis(const Reflector& r, int edge, glm::vec3& dir, int& axis) {
    switch (edge) {
        case kEdgePlusU: dir = r.tangent; axis = 0; return true;
        case kEdgeMinusU: dir = -r.tangent; axis = 0; return true;
        case kEdgePlusV: dir = r.bitangent(); axis = 1; return true;
        case kEdgeMinusV: dir = -r.bitangent(); axis = 1; return true;
        default: return false;
    }
}

}  // namespace

bool sameReflector(const Reflector& a, const Reflector& b) {
    return a.name == b.name && a.center == b.center && a.normal == b.normal && a.tangent == b.tangent &&
           a.halfExtents == b.halfExtents && a.kind == b.kind && a.reflectance == b.reflectance;
}

bool sameReflectors(const std::vector<Reflector>& a, const std::vector<Reflector>& b) {
    return std::equal(a.begin(), a.end(), b.begin(), b.end(), sameReflector);
}

std::string uniqueSnapName(const std::string& hint, const std::vector<Reflector>& existing) {
    return firstFree(hint.empty() ? std::string("reflector") : hint, 1, existing);
}

std::string uniqueCopyName(const std::string& name, const std::vector<Reflector>& existing) {
    // "puddle_1" continues as "puddle_2" rather than growing "puddle_1_2"; a bare name is copy #1.
    std::string base = name.empty() ? std::string("reflector") : name;
    unsigned long long n = 1;
    const size_t us = base.rfind('_');
    if (us != std::string::npos && us > 0 && us + 1 < base.size() && base.size() - us - 1 <= 9 &&
        std::all_of(base.begin() + us + 1, base.end(), [](char c) { return c >= '0' && c <= '9'; })) {
        n = std::stoull(base.substr(us + 1));
        base.resize(us);
    }
    return firstFree(base, n + 1, existing);
}

Reflector moveAlongPlane(const Reflector& r, const glm::vec3& delta) {
    if (!finite3(delta)) return r;
    Reflector out = r;
    out.center += delta - r.normal * glm::dot(delta, r.normal);
    return out;
}

Reflector resizeEdge(const Reflector& r, int edge, float amount) {
    glm::vec3 dir;
    int axis = 0;
    if (!edgeAxis(r, edge, dir, axis) || !std::isfinite(amount)) return r;
    const float full = 2.0f * r.halfExtents[axis];
    // Never shrink below the minimum (nor grow a reflector that is already smaller than it).
    const float minFull = std::min(full, 2.0f * kMinEditHalfExtent);
    const float newFull = std::max(full + amount, minFull);
    const float applied = newFull - full;
    Reflector out = r;
    out.halfExtents[axis] = 0.5f * newFull;
    out.center += dir * (0.5f * applied);  // the opposite edge (centre - dir * half) stays put
    return out;
}

Reflector resizeEdgeTo(const Reflector& r, int edge, const glm::vec3& point) {
    glm::vec3 dir;
    int axis = 0;
    if (!edgeAxis(r, edge, dir, axis) || !finite3(point)) return r;
    const glm::vec3 edgeCentre = r.center + dir * r.halfExtents[axis];
    return resizeEdge(r, edge, glm::dot(point - edgeCentre, dir));
}

Reflector rotateAboutNormal(const Reflector& r, float radians) {
    if (!std::isfinite(radians)) return r;
    const glm::vec3 n = r.normal;
    const float c = std::cos(radians), s = std::sin(radians);
    // Rodrigues for t orthogonal to n; then project out n and renormalise against float drift.
    glm::vec3 t = r.tangent * c + glm::cross(n, r.tangent) * s;
    t -= n * glm::dot(n, t);
    const float len = glm::length(t);
    if (!(len > 1e-6f)) return r;
    Reflector out = r;
    out.tangent = t / len;
    return out;
}

std::string makeSnappedReflector(const glm::vec3& point, const glm::vec3& normal, Reflector& out) {
    if (!finite3(point)) return "snap: surface point is not finite";
    if (!finite3(normal)) return "snap: surface normal is not finite";
    const float len = glm::length(normal);
    if (!(len > 1e-6f)) return "snap: surface normal has zero length";
    const glm::vec3 n = normal / len;
    // Project world X into the plane; near-X normals use Z instead so the tangent never wobbles.
    glm::vec3 t = glm::vec3(1, 0, 0) - n * n.x;
    if (glm::length(t) < 0.5f) t = glm::vec3(0, 0, 1) - n * n.z;
    t = glm::normalize(t);
    t = glm::normalize(t - n * glm::dot(n, t));  // second pass: orthogonal to float precision

    Reflector r;
    r.center = point;
    r.normal = n;
    r.tangent = t;
    r.halfExtents = glm::vec2(ReflectorDocument::kSnapHalfExtent);
    r.kind = scene::ReflectorKind::Opaque;
    r.reflectance = ReflectorDocument::kSnapReflectance;
    out = std::move(r);
    return "";
}

// --- ReflectorDocument -----------------------------------------------------------------------------

ReflectorDocument::ReflectorDocument(std::vector<Reflector> reflectors, std::string path) : path_(std::move(path)) {
    cur_.reflectors = std::move(reflectors);
    cur_.version = nextVersion_++;
    savedVersion_ = cur_.version;
}

void ReflectorDocument::select(std::optional<std::size_t> index) {
    cur_.selection = (index && *index < cur_.reflectors.size()) ? index : std::nullopt;
}

void ReflectorDocument::pushUndo(State before, bool freshVersion) {
    undo_.push_back(std::move(before));
    while (undo_.size() > kMaxHistory) undo_.pop_front();
    redo_.clear();
    if (freshVersion) cur_.version = nextVersion_++;
}

void ReflectorDocument::commitDrag() {
    if (!drag_) return;
    Drag drag = std::move(*drag_);
    drag_.reset();
    if (!drag.changed) return;
    if (sameReflectors(cur_.reflectors, drag.before.reflectors)) {
        cur_.version = drag.before.version;  // dragged back to the start: the same state, no step
        return;
    }
    pushUndo(std::move(drag.before), /*freshVersion=*/false);  // cur_ got its version at the first change
}

std::size_t ReflectorDocument::add(Reflector r) {
    commitDrag();
    if (r.name.empty()) r.name = uniqueSnapName("reflector", cur_.reflectors);
    else if (nameUsed(r.name, cur_.reflectors)) r.name = uniqueCopyName(r.name, cur_.reflectors);
    State before = cur_;
    cur_.reflectors.push_back(std::move(r));
    cur_.selection = cur_.reflectors.size() - 1;
    pushUndo(std::move(before));
    return cur_.reflectors.size() - 1;
}

std::optional<std::size_t> ReflectorDocument::duplicate(std::size_t index) {
    commitDrag();
    if (index >= cur_.reflectors.size()) return std::nullopt;
    Reflector copy = cur_.reflectors[index];
    copy.name = uniqueCopyName(copy.name, cur_.reflectors);
    copy.center += copy.tangent * kDuplicateOffset;
    State before = cur_;
    cur_.reflectors.push_back(std::move(copy));
    cur_.selection = cur_.reflectors.size() - 1;
    pushUndo(std::move(before));
    return cur_.reflectors.size() - 1;
}

bool ReflectorDocument::remove(std::size_t index) {
    commitDrag();
    if (index >= cur_.reflectors.size()) return false;
    State before = cur_;
    cur_.reflectors.erase(cur_.reflectors.begin() + static_cast<std::ptrdiff_t>(index));
    if (cur_.selection) {  // keep pointing at the same reflector; none if it was the removed one
        if (*cur_.selection == index) cur_.selection.reset();
        else if (*cur_.selection > index) --*cur_.selection;
    }
    pushUndo(std::move(before));
    return true;
}

bool ReflectorDocument::replace(std::size_t index, const Reflector& r) {
    if (index >= cur_.reflectors.size()) return false;
    if (sameReflector(cur_.reflectors[index], r)) return true;  // nothing changed: no undo step
    if (drag_) {
        cur_.reflectors[index] = r;
        if (!drag_->changed) {
            drag_->changed = true;
            cur_.version = nextVersion_++;  // dirty while dragging; the step is recorded at endEdit
        }
        return true;
    }
    State before = cur_;
    cur_.reflectors[index] = r;
    pushUndo(std::move(before));
    return true;
}

void ReflectorDocument::setAll(std::vector<Reflector> reflectors) {
    commitDrag();
    if (sameReflectors(cur_.reflectors, reflectors)) return;
    State before = cur_;
    cur_.reflectors = std::move(reflectors);
    if (cur_.selection && *cur_.selection >= cur_.reflectors.size()) cur_.selection.reset();
    pushUndo(std::move(before));
}

CreateResult ReflectorDocument::snapCreate(const glm::vec3& point, const glm::vec3& normal, const std::string& nameHint) {
    Reflector r;
    if (auto error = makeSnappedReflector(point, normal, r); !error.empty()) return {std::nullopt, error};
    r.name = uniqueSnapName(nameHint, cur_.reflectors);
    return {add(std::move(r)), ""};
}

bool ReflectorDocument::beginEdit(std::size_t index) {
    commitDrag();  // a begin without an end (lost mouse-up) still leaves a proper step
    if (index >= cur_.reflectors.size()) return false;
    drag_ = Drag{cur_, false};
    return true;
}

void ReflectorDocument::endEdit() { commitDrag(); }

bool ReflectorDocument::undo() {
    commitDrag();
    if (undo_.empty()) return false;
    redo_.push_back(std::move(cur_));
    cur_ = std::move(undo_.back());
    undo_.pop_back();
    return true;
}

bool ReflectorDocument::redo() {
    commitDrag();
    if (redo_.empty()) return false;
    undo_.push_back(std::move(cur_));
    while (undo_.size() > kMaxHistory) undo_.pop_front();
    cur_ = std::move(redo_.back());
    redo_.pop_back();
    return true;
}

std::string ReflectorDocument::validate() const {
    std::map<std::string, std::size_t> seen;
    for (std::size_t i = 0; i < cur_.reflectors.size(); ++i) {
        const Reflector& r = cur_.reflectors[i];
        const std::string who = "reflector " + std::to_string(i) + " '" + r.name + "': ";
        if (auto problem = scene::validateReflector(r); !problem.empty()) return who + problem;
        if (auto [it, inserted] = seen.emplace(r.name, i); !inserted)
            return who + "name: duplicate name (also reflector " + std::to_string(it->second) + ")";
    }
    return "";
}

std::string ReflectorDocument::save() {
    if (path_.empty()) return "save: the document has no file yet (use Save As)";
    return saveAs(path_);
}

std::string ReflectorDocument::saveAs(const std::string& path) {
    commitDrag();
    if (path.empty()) return "save: empty file path";
    if (auto problem = validate(); !problem.empty()) return problem;  // nothing touched on disk
    try {
        scene::saveReflectorFileAtomic(path, cur_.reflectors);
    } catch (const std::exception& e) {
        return e.what();  // already one line naming the file
    }
    path_ = path;
    savedVersion_ = cur_.version;
    return "";
}

std::string ReflectorDocument::load(const std::string& path) {
    std::vector<Reflector> loaded;
    try {
        loaded = scene::loadReflectorFile(path);
    } catch (const std::exception& e) {
        std::string msg = e.what();
        if (msg.rfind(path, 0) != 0) msg = path + ": " + msg;
        return msg;
    }
    drag_.reset();  // the dragged state is being replaced anyway
    cur_ = State{std::move(loaded), std::nullopt, nextVersion_++};
    undo_.clear();
    redo_.clear();
    savedVersion_ = cur_.version;
    path_ = path;
    return "";
}

}  // namespace ppr::app
