#pragma once
// Reflector rectangles: the analytic shapes PPR projects onto. File format (DESIGN.md, versioned):
// {"version":1,"reflectors":[{"name","center":[x,y,z],"normal":[x,y,z],"tangent":[x,y,z],
//   "half_extents":[u,v],"kind":"opaque"|"glass","reflectance":0..1}]}
// The same object (without "version") may sit in a glTF node's extras under "ppr_reflector".
#include <glm/glm.hpp>
#include <nlohmann/json_fwd.hpp>

#include <string>
#include <vector>

namespace ppr::scene {

enum class ReflectorKind { Opaque, Glass };

struct Reflector {
    std::string name;
    glm::vec3 center{0.0f};
    glm::vec3 normal{0.0f, 1.0f, 0.0f};   // unit length
    glm::vec3 tangent{1.0f, 0.0f, 0.0f};  // unit, orthogonal to normal; half_extents.x runs along it
    glm::vec2 halfExtents{1.0f};          // metres along tangent and bitangent = cross(normal, tangent)
    ReflectorKind kind = ReflectorKind::Opaque;
    float reflectance = 1.0f;             // 0..1

    glm::vec3 bitangent() const { return glm::cross(normal, tangent); }
    float planeDistance(const glm::vec3& p) const { return glm::dot(p - center, normal); }
    // True when p (assumed on/near the plane) projects inside the rectangle, grown by `margin`.
    bool containsProjected(const glm::vec3& p, float margin = 0.0f) const;
};

constexpr int kReflectorFileVersion = 1;
// Tolerances used by validation (also reported in error messages).
constexpr float kUnitTolerance = 1e-3f;       // |normal| and |tangent| must be 1 within this
constexpr float kOrthoTolerance = 1e-3f;      // |dot(normal, tangent)| must be below this
constexpr float kMinHalfExtent = 1e-4f;       // metres
// Beyond these a float32 world loses the millimetres the passes' tolerances are made of: refused, not
// rendered wrong. A reflector list longer than kMaxReflectors is refused too (PPR projects the first
// kPprMaxReflectors; the rest get planar/ray-traced/SSR only, with a warning).
constexpr float kMaxHalfExtent = 1e5f;        // metres
constexpr float kMaxCoordinate = 1e6f;        // metres, |center| per axis
constexpr size_t kMaxReflectors = 16384;

// Parses and validates one reflector object. `where` names the file and path for error messages,
// e.g. "scene.reflectors.json: reflectors[2]". Throws std::runtime_error with one line
// "<where>.<field>: <problem>" on any problem (missing/unknown field, NaN, zero extents, zero or
// non-unit normal, tangent parallel or not orthogonal to normal, reflectance outside 0..1, bad kind).
Reflector parseReflector(const nlohmann::json& j, const std::string& where);
// Parses a whole reflector file's text; `file` is used in error messages.
std::vector<Reflector> parseReflectorFile(const std::string& text, const std::string& file);
std::vector<Reflector> loadReflectorFile(const std::string& path);
// Serialises (version 1) — what the editor saves; parseReflectorFile(toJson(x)) == x.
std::string reflectorsToJson(const std::vector<Reflector>& reflectors);
nlohmann::json reflectorToJson(const Reflector& r);
// Validates an in-memory reflector (same rules as parsing); returns "" when valid, else "field: problem".
std::string validateReflector(const Reflector& r);
// Writes via a temporary file + rename, so a crash mid-save never loses the previous file.
void saveReflectorFileAtomic(const std::string& path, const std::vector<Reflector>& reflectors);

}  // namespace ppr::scene
