#include "scene/mirror.hpp"

#include <cmath>

namespace ppr::scene {

glm::mat4 reflectionMatrix(const glm::vec3& n, const glm::vec3& c) {
    glm::mat4 r(1.0f);
    for (int col = 0; col < 3; ++col)
        for (int row = 0; row < 3; ++row) r[col][row] -= 2.0f * n[row] * n[col];
    const glm::vec3 t = 2.0f * glm::dot(n, c) * n;
    r[3] = glm::vec4(t, 1.0f);
    return r;
}

glm::mat4 obliqueProjection(const glm::mat4& proj, const glm::vec4& viewPlane) {
    // projectionMatrix(): z_clip = near, w_clip = −z_view. New z_clip = w_clip − k·(plane·v), so
    // z ≤ w ⇔ plane·v ≥ 0 (the oblique near plane) and depth = 1 − k·(plane·v)/w. Inside the frustum
    // (plane·v)/w ≤ |v.xyz|/w ≤ sec(half-diagonal FOV) when the camera is behind the plane, so
    // k = 0.5·cos(half-diagonal FOV) keeps depth ≥ 0.5 out to infinity.
    const float tanX = 1.0f / std::abs(proj[0][0]), tanY = 1.0f / std::abs(proj[1][1]);
    const float k = 0.5f / std::sqrt(1.0f + tanX * tanX + tanY * tanY);
    glm::mat4 p = proj;
    for (int col = 0; col < 4; ++col) p[col][2] = proj[col][3] - k * viewPlane[col];
    return p;
}

MirrorView mirrorView(const glm::mat4& view, const glm::mat4& proj, const glm::vec3& eye, const Reflector& r, float clipOffset) {
    MirrorView m;
    const glm::mat4 reflect = reflectionMatrix(r.normal, r.center);
    m.view = view * reflect;
    m.eye = glm::vec3(reflect * glm::vec4(eye, 1.0f));
    const glm::vec4 worldPlane(r.normal, -glm::dot(r.normal, r.center) - clipOffset);
    glm::vec4 viewPlane = glm::transpose(glm::inverse(m.view)) * worldPlane;
    viewPlane /= glm::length(glm::vec3(viewPlane));
    m.proj = obliqueProjection(proj, viewPlane);
    return m;
}

bool reflectorMaybeVisible(const Reflector& r, const glm::mat4& viewProj, const glm::vec3& eye) {
    if (r.planeDistance(eye) <= 0.0f) return false;
    const glm::vec3 u = r.tangent * r.halfExtents.x, v = r.bitangent() * r.halfExtents.y;
    const glm::vec3 corners[4] = {r.center - u - v, r.center + u - v, r.center + u + v, r.center - u + v};
    int outside[5] = {0, 0, 0, 0, 0};  // x < −w, x > w, y < −w, y > w, behind the camera
    for (const glm::vec3& c : corners) {
        const glm::vec4 p = viewProj * glm::vec4(c, 1.0f);
        outside[0] += p.x < -p.w;
        outside[1] += p.x > p.w;
        outside[2] += p.y < -p.w;
        outside[3] += p.y > p.w;
        outside[4] += p.w <= 0.0f;
    }
    for (int n : outside)
        if (n == 4) return false;
    return true;
}

}  // namespace ppr::scene
