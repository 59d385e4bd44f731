#pragma once
// Camera paths for `--path` (capture, compare): one pose per frame, starting at a named or given
// camera. Pure math and text, unit-tested without a GPU. Speeds are per frame (a 60 Hz frame):
//   still   the start pose every frame (TAA's convergence and flicker)
//   animate the start pose every frame while the scene's animation plays, kFrameSeconds per frame
//           (reflections of moving things); every other path keeps the scene at rest, so that its
//           figures measure camera motion alone
//   strafe  sideways to the right, kStrafeMetresPerFrame per frame, looking ahead
//   dolly   forward along the view direction, kDollyMetresPerFrame per frame
//   orbit   around the point kOrbitRadius metres ahead, kOrbitDegreesPerFrame per frame, looking at it
//   FILE    one pose per line "x,y,z,yawDeg,pitchDeg[,fovYDeg]" (blank lines and # comments skipped)
#include "scene/camera.hpp"

#include <optional>
#include <string>
#include <vector>

namespace ppr::scene {

constexpr float kStrafeMetresPerFrame = 0.02f;
constexpr float kDollyMetresPerFrame = 0.02f;
constexpr float kOrbitRadius = 6.0f;
constexpr float kOrbitDegreesPerFrame = 0.25f;
constexpr double kFrameSeconds = 1.0 / 60.0;

const std::vector<std::string>& namedCameraPaths();  // still, animate, strafe, dolly, orbit
bool isNamedCameraPath(const std::string& name);
// The scene time of frame `frame` of the path `name` (a named path or a file): seconds on the
// animation's clock for `animate`, none (the pose as loaded) for the others.
std::optional<double> cameraPathSceneTime(const std::string& name, uint32_t frame);

// `frames` poses of a named path from `start`. Throws std::runtime_error for an unknown name.
std::vector<CameraPose> namedCameraPath(const std::string& name, const CameraPose& start, uint32_t frames);
// The poses of a path file's text; `file` names it in errors: "FILE:LINE: expected x,y,z,yawDeg,..."
// (also for an empty path). Throws std::runtime_error.
std::vector<CameraPose> parseCameraPath(const std::string& text, const std::string& file);
// True when every pose equals the first (the camera stands still: flicker is measurable).
bool isStill(const std::vector<CameraPose>& poses);

}  // namespace ppr::scene
