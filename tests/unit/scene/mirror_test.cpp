// Mirror-camera math of the planar ground truth (engine/scene/mirror.hpp).
#include "scene/camera.hpp"
#include "scene/mirror.hpp"

#include <gtest/gtest.h>

#include <random>

using namespace ppr::scene;

namespace {

Reflector floorMirror(float height) {
    Reflector r;
    r.name = "floor";
    r.center = {0.0f, height, -5.0f};
    r.normal = {0.0f, 1.0f, 0.0f};
    r.tangent = {1.0f, 0.0f, 0.0f};
    r.halfExtents = {4.0f, 4.0f};
    return r;
}

Reflector wallMirror() {
    Reflector r;
    r.name = "wall";
    r.center = {0.0f, 1.5f, -8.0f};
    r.normal = glm::normalize(glm::vec3(0.3f, 0.0f, 1.0f));
    r.tangent = glm::normalize(glm::cross(glm::vec3(0, 1, 0), r.normal));
    r.halfExtents = {3.0f, 1.5f};
    return r;
}

}  // namespace

TEST(Mirror, ReflectionIsAnInvolutionFixingThePlane) {
    const Reflector r = wallMirror();
    const glm::mat4 m = reflectionMatrix(r.normal, r.center);
    const glm::mat4 mm = m * m;
    for (int c = 0; c < 4; ++c)
        for (int k = 0; k < 4; ++k) EXPECT_NEAR(mm[c][k], c == k ? 1.0f : 0.0f, 1e-5f);
    const glm::vec3 onPlane = r.center + r.tangent * 1.3f;
    EXPECT_LT(glm::length(glm::vec3(m * glm::vec4(onPlane, 1.0f)) - onPlane), 1e-5f);
    const glm::vec3 above = r.center + r.normal * 2.0f + r.tangent * 0.5f;
    const glm::vec3 below = glm::vec3(m * glm::vec4(above, 1.0f));
    EXPECT_NEAR(r.planeDistance(below), -2.0f, 1e-5f);
}

TEST(Mirror, ObliqueProjectionClipsAtThePlaneAndKeepsEverythingInFrontOfIt) {
    for (const Reflector& r : {floorMirror(0.0f), floorMirror(0.4f), wallMirror()}) {
        CameraPose cam;
        cam.position = {0.5f, 1.7f, 2.0f};
        cam.yawDeg = 5.0f;
        cam.pitchDeg = -12.0f;
        const glm::mat4 view = viewMatrix(cam), proj = projectionMatrix(60.0f, 16.0f / 9.0f, kNearPlane);
        const MirrorView mv = mirrorView(view, proj, cam.position, r, 0.0f);
        const glm::mat4 vp = mv.proj * mv.view;
        const glm::mat4 mainVp = proj * view;
        const glm::mat4 reflect = reflectionMatrix(r.normal, r.center);
        std::mt19937 rng(7);
        std::uniform_real_distribution<float> u(-60.0f, 60.0f);
        int kept = 0, clipped = 0;
        for (int i = 0; i < 20000; ++i) {
            const glm::vec3 x(u(rng), u(rng) * 0.3f + 10.0f, u(rng));
            const glm::vec4 c = vp * glm::vec4(x, 1.0f);
            if (c.w <= 0.0f || std::abs(c.x) > c.w || std::abs(c.y) > c.w) continue;  // outside the side planes
            const float d = r.planeDistance(x);
            if (d > 1e-3f) {
                // In front of the reflector: never clipped by depth, and seen where the main camera sees
                // its mirror image.
                EXPECT_GE(c.z / c.w, 0.5f - 1e-4f);
                EXPECT_LE(c.z, c.w * (1.0f + 1e-6f));
                const glm::vec4 m = mainVp * reflect * glm::vec4(x, 1.0f);
                EXPECT_NEAR(c.x / c.w, m.x / m.w, 1e-3f);
                EXPECT_NEAR(c.y / c.w, m.y / m.w, 1e-3f);
                ++kept;
            } else if (d < -1e-3f) {
                EXPECT_GT(c.z, c.w) << "a point behind the reflector plane must be clipped";
                ++clipped;
            }
        }
        EXPECT_GT(kept, 100);
        EXPECT_GT(clipped, 20);
    }
}

TEST(Mirror, DepthDecreasesAlongEveryRayBeyondThePlane) {
    const Reflector r = floorMirror(0.0f);
    CameraPose cam;
    cam.position = {0.0f, 1.5f, 3.0f};
    cam.pitchDeg = -20.0f;
    const glm::mat4 view = viewMatrix(cam), proj = projectionMatrix(70.0f, 1.5f, kNearPlane);
    const MirrorView mv = mirrorView(view, proj, cam.position, r);
    const glm::mat4 vp = mv.proj * mv.view;
    int rays = 0;
    for (float sx : {-0.9f, 0.0f, 0.8f})
        for (float sy : {-0.8f, 0.1f, 0.9f}) {
            // The mirrored camera's ray through NDC (sx, sy), from where it crosses the reflector plane
            // (depth 1) outwards: depth must fall monotonically and stay ≥ 0.5.
            const glm::vec4 a = glm::inverse(vp) * glm::vec4(sx, sy, 1.0f, 1.0f);
            const glm::vec3 p0 = glm::vec3(a) / a.w;
            if ((mv.view * glm::vec4(p0, 1.0f)).z >= 0.0f) continue;  // this ray meets the plane behind the camera
            ++rays;
            EXPECT_NEAR(r.planeDistance(p0), 2e-3f, 1e-4f);  // the default clip offset
            const glm::vec3 dir = glm::normalize(p0 - mv.eye);
            float previous = 2.0f;
            for (float t = 0.0f; t < 500.0f; t = t * 1.3f + 0.05f) {
                const glm::vec4 c = vp * glm::vec4(p0 + dir * t, 1.0f);
                const float depth = c.z / c.w;
                EXPECT_LT(depth, previous + 1e-6f);
                EXPECT_GE(depth, 0.5f - 1e-4f);
                previous = depth;
            }
        }
    EXPECT_GE(rays, 3);
    EXPECT_NEAR(mv.eye.y, -1.5f, 1e-5f);
}

TEST(Mirror, VisibilityRejectsBackSideAndOutOfFrustum) {
    const Reflector r = floorMirror(0.0f);
    CameraPose cam;
    cam.position = {0.0f, 1.7f, 2.0f};
    cam.pitchDeg = -20.0f;
    const glm::mat4 vp = projectionMatrix(60.0f, 1.0f, kNearPlane) * viewMatrix(cam);
    EXPECT_TRUE(reflectorMaybeVisible(r, vp, cam.position));
    CameraPose below = cam;
    below.position.y = -1.0f;
    below.pitchDeg = 20.0f;
    EXPECT_FALSE(reflectorMaybeVisible(r, projectionMatrix(60.0f, 1.0f, kNearPlane) * viewMatrix(below), below.position));
    CameraPose away = cam;
    away.yawDeg = 180.0f;  // looking down +Z, the floor mirror is behind
    EXPECT_FALSE(reflectorMaybeVisible(r, projectionMatrix(60.0f, 1.0f, kNearPlane) * viewMatrix(away), away.position));
    CameraPose up = cam;
    up.pitchDeg = 60.0f;  // looking at the sky
    EXPECT_FALSE(reflectorMaybeVisible(r, projectionMatrix(60.0f, 1.0f, kNearPlane) * viewMatrix(up), up.position));
}
