// Camera paths of --path: the named paths' motion per frame and path files with their errors.
#include "scene/camera_path.hpp"

#include "test_util.hpp"

#include <cmath>

using namespace ppr::scene;
using ppr::scene::test::expectError;

namespace {

const CameraPose kStart{{1.0f, 1.6f, 4.0f}, 90.0f, -10.0f, 60.0f};  // looking down +X

TEST(CameraPath, StillRepeatsTheStart) {
    const std::vector<CameraPose> p = namedCameraPath("still", kStart, 5);
    ASSERT_EQ(p.size(), 5u);
    EXPECT_TRUE(isStill(p));
    EXPECT_EQ(p[4].position, kStart.position);
}

TEST(CameraPath, AnimateHoldsTheCameraAndRunsTheSceneClock) {
    const std::vector<CameraPose> p = namedCameraPath("animate", kStart, 4);
    EXPECT_TRUE(isStill(p));
    ASSERT_TRUE(cameraPathSceneTime("animate", 0).has_value());
    EXPECT_EQ(*cameraPathSceneTime("animate", 0), 0.0);
    EXPECT_DOUBLE_EQ(*cameraPathSceneTime("animate", 3), 3 * kFrameSeconds);
    // Every other path keeps the scene at rest, so its figures measure camera motion alone.
    for (const char* name : {"still", "strafe", "dolly", "orbit", "poses.txt"}) EXPECT_FALSE(cameraPathSceneTime(name, 3)) << name;
}

TEST(CameraPath, StrafeMovesRightAndDollyForward) {
    const std::vector<CameraPose> strafe = namedCameraPath("strafe", kStart, 11);
    const std::vector<CameraPose> dolly = namedCameraPath("dolly", kStart, 11);
    EXPECT_FALSE(isStill(strafe));
    // Yaw 90 looks down +X, so right is +Z; forward has the pitch in it.
    const glm::vec3 moved = strafe[10].position - kStart.position, ahead = dolly[10].position - kStart.position;
    EXPECT_NEAR(moved.z, 10 * kStrafeMetresPerFrame, 1e-5f);
    EXPECT_NEAR(moved.x, 0.0f, 1e-5f);
    EXPECT_NEAR(glm::length(ahead), 10 * kDollyMetresPerFrame, 1e-5f);
    EXPECT_NEAR(glm::dot(glm::normalize(ahead), viewDirection(kStart.yawDeg, kStart.pitchDeg)), 1.0f, 1e-5f);
    EXPECT_EQ(strafe[10].yawDeg, kStart.yawDeg);
}

TEST(CameraPath, OrbitKeepsLookingAtThePivot) {
    const std::vector<CameraPose> p = namedCameraPath("orbit", kStart, 200);
    const glm::vec3 pivot = kStart.position + viewDirection(kStart.yawDeg, kStart.pitchDeg) * kOrbitRadius;
    for (const CameraPose& pose : {p[1], p[57], p[199]}) {
        const glm::vec3 toPivot = pivot - pose.position;
        EXPECT_NEAR(glm::length(toPivot), kOrbitRadius, 1e-4f);
        EXPECT_NEAR(glm::dot(glm::normalize(toPivot), viewDirection(pose.yawDeg, pose.pitchDeg)), 1.0f, 1e-5f);
    }
    EXPECT_NEAR(p[199].yawDeg - kStart.yawDeg, 199 * kOrbitDegreesPerFrame, 1e-4f);
}

TEST(CameraPath, UnknownNameThrows) { expectError([] { namedCameraPath("spiral", kStart, 3); }, {"--path spiral"}); }

TEST(CameraPath, FileLinesCommentsAndErrors) {
    const std::vector<CameraPose> p = parseCameraPath("# a path\n0,1,2,90,0\n\n  3,4,5,10,-5,45  \r\n", "walk.txt");
    ASSERT_EQ(p.size(), 2u);
    EXPECT_EQ(p[1].position, glm::vec3(3, 4, 5));
    EXPECT_EQ(p[1].fovYDeg, 45.0f);
    expectError([] { parseCameraPath("0,1,2,90,0\nhall\n", "walk.txt"); }, {"walk.txt:2: expected x,y,z"});
    expectError([] { parseCameraPath("0,1,nan,90,0\n", "walk.txt"); }, {"walk.txt:1:"});
    expectError([] { parseCameraPath("# nothing\n", "walk.txt"); }, {"walk.txt: no camera poses"});
}

}  // namespace
