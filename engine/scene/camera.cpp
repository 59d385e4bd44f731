// Camera math of the interface contract: yaw/pitch convention, view matrix and the reverse-Z,
// infinite-far, Vulkan-clip-space projection.
#include "scene/camera.hpp"

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>

namespace ppr::scene {

glm::vec3 viewDirection(float yawDeg, float pitchDeg) {
    const float yaw = glm::radians(yawDeg), pitch = glm::radians(pitchDeg);
    return {std::sin(yaw) * std::cos(pitch), std::sin(pitch), -std::cos(yaw) * std::cos(pitch)};
}

void yawPitchFromDirection(const glm::vec3& dir, float& yawDeg, float& pitchDeg) {
    const float len = glm::length(dir);
    if (!std::isfinite(len) || len < 1e-12f) {
        yawDeg = pitchDeg = 0.0f;
        return;
    }
    const glm::vec3 d = dir / len;
    pitchDeg = std::clamp(glm::degrees(std::asin(std::clamp(d.y, -1.0f, 1.0f))), -89.9f, 89.9f);
    // Straight up/down has no yaw; atan2(0, 0) = 0 keeps it defined.
    yawDeg = glm::degrees(std::atan2(d.x, -d.z));
}

namespace {
float radicalInverse(uint32_t index, uint32_t base) {
    float result = 0.0f, digit = 1.0f / static_cast<float>(base);
    for (; index > 0; index /= base, digit /= static_cast<float>(base)) result += static_cast<float>(index % base) * digit;
    return result;
}
}  // namespace

glm::vec2 haltonJitter(uint32_t frame) {
    const uint32_t index = frame % kJitterLength + 1;
    return {radicalInverse(index, 2) - 0.5f, radicalInverse(index, 3) - 0.5f};
}

glm::mat4 jitteredProjection(const glm::mat4& proj, glm::vec2 offsetPixels, glm::vec2 screenSize) {
    // Clip x' = x + dx·w, so NDC x' = x/w + dx: a translation in NDC, whatever the projection.
    glm::mat4 shift(1.0f);
    shift[3][0] = 2.0f * offsetPixels.x / screenSize.x;
    shift[3][1] = 2.0f * offsetPixels.y / screenSize.y;
    return shift * proj;
}

glm::mat4 viewMatrix(const CameraPose& pose) {
    // Same as glm::lookAt(pos, pos + dir, +Y), but the right vector comes from yaw alone so the
    // matrix stays defined at pitch ±90 where dir is parallel to +Y.
    const float yaw = glm::radians(pose.yawDeg);
    const glm::vec3 f = viewDirection(pose.yawDeg, pose.pitchDeg);
    const glm::vec3 s{std::cos(yaw), 0.0f, std::sin(yaw)};  // = normalize(cross(f, +Y))
    const glm::vec3 u = glm::cross(s, f);
    glm::mat4 m(1.0f);
    m[0][0] = s.x; m[1][0] = s.y; m[2][0] = s.z;
    m[0][1] = u.x; m[1][1] = u.y; m[2][1] = u.z;
    m[0][2] = -f.x; m[1][2] = -f.y; m[2][2] = -f.z;
    m[3][0] = -glm::dot(s, pose.position);
    m[3][1] = -glm::dot(u, pose.position);
    m[3][2] = glm::dot(f, pose.position);
    return m;
}

glm::mat4 projectionMatrix(float fovYDeg, float aspect, float nearPlane) {
    // clip = (x·f/aspect, −y·f, near, −z_view): depth = near / distance (1 at the near plane, → 0 at
    // infinity); the negative y scale puts world +Y at the top of a Vulkan image (NDC y = −1).
    // The y flip mirrors winding: counter-clockwise front faces appear clockwise in framebuffer space.
    const float f = 1.0f / std::tan(glm::radians(fovYDeg) * 0.5f);
    glm::mat4 p(0.0f);
    p[0][0] = f / aspect;
    p[1][1] = -f;
    p[2][3] = -1.0f;
    p[3][2] = nearPlane;
    return p;
}

}  // namespace ppr::scene
