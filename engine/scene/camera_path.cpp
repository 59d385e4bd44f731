#include "scene/camera_path.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace ppr::scene {

const std::vector<std::string>& namedCameraPaths() {
    static const std::vector<std::string> names = {"still", "animate", "strafe", "dolly", "orbit"};
    return names;
}

bool isNamedCameraPath(const std::string& name) {
    const std::vector<std::string>& n = namedCameraPaths();
    return std::find(n.begin(), n.end(), name) != n.end();
}

std::vector<CameraPose> namedCameraPath(const std::string& name, const CameraPose& start, uint32_t frames) {
    if (!isNamedCameraPath(name)) throw std::runtime_error("--path " + name + ": expected still, animate, strafe, dolly, orbit or a file");
    const glm::vec3 forward = viewDirection(start.yawDeg, start.pitchDeg);
    const float yaw = glm::radians(start.yawDeg);
    const glm::vec3 right{std::cos(yaw), 0.0f, std::sin(yaw)};  // as viewMatrix's
    const glm::vec3 pivot = start.position + forward * kOrbitRadius;
    std::vector<CameraPose> poses(frames, start);
    for (uint32_t i = 0; i < frames; ++i) {
        CameraPose& p = poses[i];
        const float t = static_cast<float>(i);
        if (name == "strafe") p.position = start.position + right * (kStrafeMetresPerFrame * t);
        else if (name == "dolly") p.position = start.position + forward * (kDollyMetresPerFrame * t);
        else if (name == "orbit") {
            // Rotate the eye about the vertical through the pivot, and the view with it.
            const float angle = glm::radians(kOrbitDegreesPerFrame * t);
            const glm::vec3 offset = start.position - pivot;
            const float c = std::cos(angle), s = std::sin(angle);
            p.position = pivot + glm::vec3(c * offset.x - s * offset.z, offset.y, s * offset.x + c * offset.z);
            p.yawDeg = start.yawDeg + kOrbitDegreesPerFrame * t;
        }
    }
    return poses;
}

std::optional<double> cameraPathSceneTime(const std::string& name, uint32_t frame) {
    if (name != "animate") return std::nullopt;
    return kFrameSeconds * frame;
}

std::vector<CameraPose> parseCameraPath(const std::string& text, const std::string& file) {
    std::vector<CameraPose> poses;
    std::istringstream in(text);
    std::string line;
    for (uint32_t number = 1; std::getline(in, line); ++number) {
        const size_t first = line.find_first_not_of(" \t\r");
        if (first == std::string::npos || line[first] == '#') continue;
        const size_t last = line.find_last_not_of(" \t\r");
        const std::string spec = line.substr(first, last - first + 1);
        std::optional<CameraPose> pose;
        try {
            pose = parseCameraSpec(spec);
        } catch (const std::exception& e) {
            throw std::runtime_error(file + ":" + std::to_string(number) + ": " + e.what());
        }
        if (!pose) throw std::runtime_error(file + ":" + std::to_string(number) + ": expected x,y,z,yawDeg,pitchDeg[,fovYDeg]");
        poses.push_back(*pose);
    }
    if (poses.empty()) throw std::runtime_error(file + ": no camera poses (expected one x,y,z,yawDeg,pitchDeg[,fovYDeg] per line)");
    return poses;
}

bool isStill(const std::vector<CameraPose>& poses) {
    for (const CameraPose& p : poses) {
        const CameraPose& a = poses.front();
        if (p.position != a.position || p.yawDeg != a.yawDeg || p.pitchDeg != a.pitchDeg || p.fovYDeg != a.fovYDeg) return false;
    }
    return true;
}

}  // namespace ppr::scene
