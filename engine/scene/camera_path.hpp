#pragma once
// Camera paths for `--path` (capture, compare): one pose per frame, starting at a named or given
// camera. Pure math and text, unit-tested without a GPU. Speeds are per frame (a 60 Hz frame):
//   still   the start pose every frame (TAA's convergence and flicker)
//   strafe  sideways to the right, kStrafeMetresPerFrame per frame, looking ahead
//   dolly   forward along the view direction, kDollyMetresPerFrame per frame
//   orbit   around the point kOrbitRadius metres ahead, kOrbitDegreesPerFrame per frame, looking at it
//   FILE    one pose per line "x,y,z,yawDeg,pitchDeg[,fovYDeg]" (blank lines and # comments skipped)
#include "scene/camera.hpp"

#include <string>
#include <vector>

namespace ppr::scene {

constexpr float kStrafeMetresPerFrame = 0.02f;
constexpr float kDollyMetresPerFrame = 0.02f;
constexpr float kOrbitRadius = 6.0f;
constexpr float kOrbitDegreesPerFrame = 0.25f;

const std::vector<std::string>& namedCameraPaths();  // still, strafe, dolly, orbit
bool isNamedCameraPath(const std::string& name);

// `frames` poses of a named path from `start`. Throws std::runtime_error for an unknown name.
std::vector<CameraPose> namedCameraPath(const std::string& name, const CameraPose& start, uint32_t frames);
// The poses of a path file's text; `file` names it in errors: "FILE:LINE: expected x,y,z,yawDeg,..."
// (also for an empty path). Throws std::runtime_error.
std::vector<CameraPose> parseCameraPath(const std::string& text, const std::string& file);
// True when every pose equals the first (the camera stands still: flicker is measurable).
bool isStill(const std::vector<CameraPose>& poses);

}  // namespace ppr::scene
