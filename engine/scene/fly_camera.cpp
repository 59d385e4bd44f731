// Fly camera: WASD/QE translation along the view frame, mouse look, wheel-scaled speed.
#include "scene/camera.hpp"

#include <algorithm>
#include <cmath>

namespace ppr::scene {

namespace {
float sane(float v, float lo, float hi) { return std::isfinite(v) ? std::clamp(v, lo, hi) : 0.0f; }
}  // namespace

void FlyCamera::update(const FlyCameraInput& in) {
    // Garbage input (NaN from a driver, huge dt after a breakpoint) must never poison the pose.
    const float dx = sane(in.mouseDx, -1e4f, 1e4f), dy = sane(in.mouseDy, -1e4f, 1e4f);
    pose.yawDeg += dx * degreesPerPixel;
    pose.yawDeg = std::remainder(pose.yawDeg, 360.0f);  // keep yaw within ±180 as it accumulates
    pose.pitchDeg = std::clamp(pose.pitchDeg - dy * degreesPerPixel, -89.0f, 89.0f);

    const glm::vec3 forward = viewDirection(pose.yawDeg, pose.pitchDeg);
    const glm::vec3 right = glm::normalize(glm::cross(forward, glm::vec3(0, 1, 0)));
    glm::vec3 move = forward * sane(in.forward, -1, 1) + right * sane(in.right, -1, 1) +
                     glm::vec3(0, 1, 0) * sane(in.up, -1, 1);
    if (const float len = glm::length(move); len > 1.0f) move /= len;  // diagonals are not faster
    pose.position += move * speed * sane(in.dt, 0.0f, 1.0f);
}

void FlyCamera::scrollSpeed(float wheelSteps) {
    if (!std::isfinite(wheelSteps)) return;
    speed = std::clamp(speed * std::pow(1.2f, std::clamp(wheelSteps, -100.0f, 100.0f)), 0.05f, 200.0f);
}

}  // namespace ppr::scene
