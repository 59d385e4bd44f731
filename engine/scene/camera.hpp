#pragma once
// Camera conventions (DESIGN.md contract): metres, +Y up, view direction
// (sin yaw·cos pitch, sin pitch, −cos yaw·cos pitch); yaw 0 looks down −Z, yaw 90 down +X,
// positive pitch looks up; default vertical FOV 60°.
// Projection: reverse-Z (depth 1 at the near plane, 0 at infinity), infinite far plane, Vulkan clip
// space (y down in NDC is handled by a negative y scale, depth 0..1).
#include <glm/glm.hpp>

#include <cstdint>
#include <optional>
#include <string>

namespace ppr::scene {

struct CameraPose {
    glm::vec3 position{0.0f};
    float yawDeg = 0.0f;
    float pitchDeg = 0.0f;
    float fovYDeg = 60.0f;
};

glm::vec3 viewDirection(float yawDeg, float pitchDeg);
// Yaw/pitch (degrees) of a unit direction (inverse of viewDirection; pitch clamped to ±89.9).
void yawPitchFromDirection(const glm::vec3& dir, float& yawDeg, float& pitchDeg);
glm::mat4 viewMatrix(const CameraPose& pose);
glm::mat4 projectionMatrix(float fovYDeg, float aspect, float nearPlane);  // reverse-Z, infinite far
constexpr float kNearPlane = 0.05f;

// TAA's sub-pixel jitter: the Halton (2, 3) sequence, samples 1..kJitterLength repeating, as an offset
// in pixels in (-0.5, 0.5)². Sample 0 (the origin of both bases) is skipped: it would be a corner.
constexpr uint32_t kJitterLength = 16;
glm::vec2 haltonJitter(uint32_t frame);
// `proj` moved by `offsetPixels` on a screen of `screenSize` pixels: every projected point lands that
// many pixels further right/down (NDC x and y), depth untouched.
glm::mat4 jitteredProjection(const glm::mat4& proj, glm::vec2 offsetPixels, glm::vec2 screenSize);

// "x,y,z,yawDeg,pitchDeg[,fovYDeg]" → pose; nullopt when `text` is not in that form (then it is a
// camera name). Throws std::runtime_error for a numeric form with NaN/inf or out-of-range FOV.
std::optional<CameraPose> parseCameraSpec(const std::string& text);

// WASD/QE fly camera with mouse look; pure math so it can be unit-tested.
struct FlyCameraInput {
    float forward = 0.0f, right = 0.0f, up = 0.0f;  // -1..1
    float mouseDx = 0.0f, mouseDy = 0.0f;           // pixels, only while looking
    float dt = 0.0f;                                // seconds
};
class FlyCamera {
public:
    CameraPose pose;
    float speed = 3.0f;            // m/s, changed by the wheel
    float degreesPerPixel = 0.15f;
    void update(const FlyCameraInput& in);
    void scrollSpeed(float wheelSteps);  // speed *= 1.2^steps, clamped
};

}  // namespace ppr::scene
