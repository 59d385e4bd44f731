// Camera conventions of the contract: direction from yaw/pitch, view/projection matrices
// (reverse-Z, Vulkan y), --camera parsing and the fly camera.
#include "scene/camera.hpp"

#include "test_util.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

using namespace ppr::scene;
using ppr::scene::test::expectError;

namespace {

void expectVec(const glm::vec3& a, const glm::vec3& b, float eps = 1e-5f) {
    EXPECT_NEAR(a.x, b.x, eps);
    EXPECT_NEAR(a.y, b.y, eps);
    EXPECT_NEAR(a.z, b.z, eps);
}

glm::vec3 ndc(const glm::mat4& viewProj, const glm::vec3& world) {
    const glm::vec4 c = viewProj * glm::vec4(world, 1.0f);
    return glm::vec3(c) / c.w;
}

}  // namespace

TEST(Camera, ViewDirectionConvention) {
    expectVec(viewDirection(0, 0), {0, 0, -1});   // yaw 0 looks down -Z
    expectVec(viewDirection(90, 0), {1, 0, 0});   // yaw 90 looks down +X
    expectVec(viewDirection(180, 0), {0, 0, 1});
    expectVec(viewDirection(-90, 0), {-1, 0, 0});
    expectVec(viewDirection(0, 90), {0, 1, 0});   // positive pitch looks up
    expectVec(viewDirection(0, 30), {0, 0.5f, -std::sqrt(3.0f) / 2});
    expectVec(viewDirection(90, -30), {std::sqrt(3.0f) / 2, -0.5f, 0});
}

TEST(Camera, YawPitchFromDirectionInvertsViewDirection) {
    for (float yaw = -175; yaw <= 180; yaw += 12.5f)
        for (float pitch = -85; pitch <= 85; pitch += 8.5f) {
            float y = 0, p = 0;
            yawPitchFromDirection(viewDirection(yaw, pitch) * 3.0f, y, p);  // length does not matter
            EXPECT_NEAR(y, yaw, 1e-3f);
            EXPECT_NEAR(p, pitch, 1e-3f);
        }
    float y = 1, p = 1;
    yawPitchFromDirection({0, 1, 0}, y, p);
    EXPECT_FLOAT_EQ(p, 89.9f);  // clamped
    yawPitchFromDirection({0, 0, 0}, y, p);
    EXPECT_EQ(y, 0.0f);
    EXPECT_EQ(p, 0.0f);
}

TEST(Camera, ViewMatrixMatchesLookAt) {
    CameraPose pose{{1, 2, 3}, 37, -21, 60};
    const glm::vec3 dir = viewDirection(pose.yawDeg, pose.pitchDeg);
    const glm::mat4 expected = glm::lookAt(pose.position, pose.position + dir, glm::vec3(0, 1, 0));
    const glm::mat4 v = viewMatrix(pose);
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) EXPECT_NEAR(v[c][r], expected[c][r], 1e-5f) << c << "," << r;
    // A point 5 m ahead lands on the -Z axis of view space.
    expectVec(glm::vec3(v * glm::vec4(pose.position + 5.0f * dir, 1)), {0, 0, -5}, 1e-4f);
    // Straight up stays well defined.
    const glm::mat4 up = viewMatrix({{0, 0, 0}, 0, 90, 60});
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) EXPECT_TRUE(std::isfinite(up[c][r]));
    expectVec(glm::vec3(up * glm::vec4(0, 2, 0, 1)), {0, 0, -2});
}

TEST(Camera, ProjectionIsReverseZInfiniteVulkan) {
    const float nearPlane = kNearPlane;
    const glm::mat4 proj = projectionMatrix(60, 16.0f / 9.0f, nearPlane);
    EXPECT_LT(proj[1][1], 0.0f) << "y must be flipped for Vulkan";
    CameraPose pose{{0, 1, 0}, 0, 0, 60};
    const glm::mat4 vp = proj * viewMatrix(pose);

    EXPECT_NEAR(ndc(vp, {0, 1, -nearPlane}).z, 1.0f, 1e-5f);                     // near plane → depth 1
    EXPECT_NEAR(ndc(vp, {0, 1, -10}).z, nearPlane / 10, 1e-6f);                  // depth = near / distance
    EXPECT_LT(ndc(vp, {0, 1, -1e6f}).z, 1e-6f);                                  // → 0 towards infinity
    EXPECT_GT(ndc(vp, {0, 1, -1e6f}).z, 0.0f);
    EXPECT_GT(ndc(vp, {0, 1, -1}).z, ndc(vp, {0, 1, -2}).z);                     // nearer = larger depth

    // World +Y above the view centre is in the top half of a Vulkan image: NDC y < 0.
    EXPECT_LT(ndc(vp, {0, 2, -5}).y, 0.0f);
    EXPECT_GT(ndc(vp, {0, 0, -5}).y, 0.0f);
    EXPECT_GT(ndc(vp, {1, 1, -5}).x, 0.0f);  // +X is to the right when looking down -Z
    // The vertical FOV edge maps to |y| = 1: tan(30°) at distance 1.
    EXPECT_NEAR(ndc(vp, {0, 1 + std::tan(glm::radians(30.0f)), -1}).y, -1.0f, 1e-5f);
    // Aspect: the horizontal edge is aspect times wider.
    EXPECT_NEAR(ndc(vp, {16.0f / 9.0f * std::tan(glm::radians(30.0f)), 1, -1}).x, 1.0f, 1e-5f);
}

TEST(Camera, ParseCameraSpec) {
    auto pose = parseCameraSpec("1,2,3,90,-10");
    ASSERT_TRUE(pose.has_value());
    EXPECT_EQ(pose->position, glm::vec3(1, 2, 3));
    EXPECT_EQ(pose->yawDeg, 90.0f);
    EXPECT_EQ(pose->pitchDeg, -10.0f);
    EXPECT_EQ(pose->fovYDeg, 60.0f);  // default
    pose = parseCameraSpec(" -1.5, 0 ,2e1,0,0, 45 ");
    ASSERT_TRUE(pose.has_value());
    EXPECT_EQ(pose->position, glm::vec3(-1.5f, 0, 20));
    EXPECT_EQ(pose->fovYDeg, 45.0f);

    // Not the numeric form: a camera name.
    EXPECT_FALSE(parseCameraSpec("MainCam").has_value());
    EXPECT_FALSE(parseCameraSpec("kitchen view").has_value());
    EXPECT_FALSE(parseCameraSpec("Cam,1").has_value());
    EXPECT_FALSE(parseCameraSpec("nan").has_value());
    EXPECT_FALSE(parseCameraSpec("inf").has_value());
    EXPECT_FALSE(parseCameraSpec("").has_value());

    expectError([] { parseCameraSpec("1,2,3"); }, {"--camera: ", "5 or 6", "got 3", "'1,2,3'"});
    expectError([] { parseCameraSpec("1,2,x,4,5"); }, {"--camera: ", "'x' is not a number"});
    expectError([] { parseCameraSpec("1,2,3,4,5,"); }, {"--camera: ", "'' is not a number"});
    expectError([] { parseCameraSpec("7"); }, {"--camera: ", "got 1"});
    expectError([] { parseCameraSpec("1,2,3,4,5,6,7"); }, {"--camera", "5 or 6"});
    expectError([] { parseCameraSpec("1,2,3,4,nan"); }, {"--camera", "pitchDeg", "not a finite"});
    expectError([] { parseCameraSpec("inf,2,3,4,5"); }, {"--camera", "x", "not a finite"});
    expectError([] { parseCameraSpec("0,0,0,0,95"); }, {"--camera", "pitchDeg", "[-90, 90]"});
    expectError([] { parseCameraSpec("0,0,0,0,0,180"); }, {"--camera", "fovYDeg", "(1, 179)"});
    expectError([] { parseCameraSpec("0,0,0,0,0,1"); }, {"--camera", "fovYDeg"});
    EXPECT_TRUE(parseCameraSpec("0,0,0,0,90").has_value());  // the ends of the pitch range are valid
}

TEST(FlyCamera, MovesAlongViewFrame) {
    FlyCamera cam;
    cam.speed = 2.0f;
    cam.pose.yawDeg = 90;  // looking down +X
    cam.update({.forward = 1, .dt = 0.5f});
    expectVec(cam.pose.position, {1, 0, 0});
    cam.update({.right = 1, .dt = 0.5f});  // right of +X is +Z
    expectVec(cam.pose.position, {1, 0, 1});
    cam.update({.up = -1, .dt = 1.0f});
    expectVec(cam.pose.position, {1, -2, 1});

    FlyCamera pitched;
    pitched.pose.pitchDeg = 45;
    pitched.speed = 1;
    pitched.update({.forward = 1, .dt = 1});  // forward follows pitch
    expectVec(pitched.pose.position, viewDirection(0, 45));
    pitched.pose.position = {};
    pitched.update({.forward = 1, .right = 1, .dt = 1});
    EXPECT_NEAR(glm::length(pitched.pose.position), 1.0f, 1e-5f) << "diagonal movement is not faster";
}

TEST(FlyCamera, MouseLookAndClamp) {
    FlyCamera cam;
    cam.degreesPerPixel = 0.15f;
    cam.update({.mouseDx = 100, .mouseDy = 0});
    EXPECT_NEAR(cam.pose.yawDeg, 15.0f, 1e-4f);
    cam.update({.mouseDy = 100});  // mouse down looks down
    EXPECT_NEAR(cam.pose.pitchDeg, -15.0f, 1e-4f);
    cam.update({.mouseDy = -10000});
    EXPECT_FLOAT_EQ(cam.pose.pitchDeg, 89.0f);
    cam.update({.mouseDy = 10000});
    EXPECT_FLOAT_EQ(cam.pose.pitchDeg, -89.0f);
    const CameraPose before = cam.pose;
    cam.update({.forward = NAN, .mouseDx = NAN, .dt = 1});  // garbage input leaves the pose intact
    EXPECT_EQ(cam.pose.position, before.position);
    EXPECT_EQ(cam.pose.yawDeg, before.yawDeg);
}

TEST(FlyCamera, ScrollSpeed) {
    FlyCamera cam;
    cam.speed = 3.0f;
    cam.scrollSpeed(1);
    EXPECT_NEAR(cam.speed, 3.6f, 1e-5f);
    cam.scrollSpeed(-2);
    EXPECT_NEAR(cam.speed, 2.5f, 1e-5f);
    cam.scrollSpeed(1000);
    EXPECT_FLOAT_EQ(cam.speed, 200.0f);
    cam.scrollSpeed(-1000);
    EXPECT_FLOAT_EQ(cam.speed, 0.05f);
}

TEST(CameraJitter, HaltonTwoThreeSamplesInsideThePixelAndRepeating) {
    // Halton index 1 = (1/2, 1/3), index 2 = (1/4, 2/3), index 3 = (3/4, 1/9), minus 0.5.
    EXPECT_NEAR(haltonJitter(0).x, 0.0f, 1e-6f);
    EXPECT_NEAR(haltonJitter(0).y, 1.0f / 3.0f - 0.5f, 1e-6f);
    EXPECT_NEAR(haltonJitter(1).x, -0.25f, 1e-6f);
    EXPECT_NEAR(haltonJitter(1).y, 2.0f / 3.0f - 0.5f, 1e-6f);
    EXPECT_NEAR(haltonJitter(2).x, 0.25f, 1e-6f);
    EXPECT_NEAR(haltonJitter(2).y, 1.0f / 9.0f - 0.5f, 1e-6f);
    glm::vec2 mean(0.0f);
    for (uint32_t i = 0; i < kJitterLength; ++i) {
        const glm::vec2 j = haltonJitter(i);
        EXPECT_GT(j.x, -0.5f);
        EXPECT_LT(j.x, 0.5f);
        EXPECT_GT(j.y, -0.5f);
        EXPECT_LT(j.y, 0.5f);
        EXPECT_EQ(haltonJitter(i + kJitterLength), j);
        mean += j / float(kJitterLength);
    }
    // A low-discrepancy sequence is centred on the pixel (within a sixteenth of a pixel here).
    EXPECT_LT(std::abs(mean.x), 1.0f / 16.0f);
    EXPECT_LT(std::abs(mean.y), 1.0f / 16.0f);
}

TEST(CameraJitter, JitteredProjectionMovesEveryPointByTheOffsetInPixels) {
    const glm::vec2 screen(640.0f, 360.0f), offset(0.3f, -0.2f);
    const glm::mat4 proj = projectionMatrix(60.0f, screen.x / screen.y, kNearPlane);
    const glm::mat4 jittered = jitteredProjection(proj, offset, screen);
    for (const glm::vec3 p : {glm::vec3(0.0f, 0.0f, -1.0f), glm::vec3(2.0f, -1.0f, -7.0f), glm::vec3(-30.0f, 4.0f, -300.0f)}) {
        const glm::vec4 a = proj * glm::vec4(p, 1.0f), b = jittered * glm::vec4(p, 1.0f);
        const glm::vec2 pixelsA = glm::vec2(a) / a.w * 0.5f * screen, pixelsB = glm::vec2(b) / b.w * 0.5f * screen;
        EXPECT_NEAR(pixelsB.x - pixelsA.x, offset.x, 1e-3f);
        EXPECT_NEAR(pixelsB.y - pixelsA.y, offset.y, 1e-3f);
        EXPECT_FLOAT_EQ(b.z / b.w, a.z / a.w);
    }
}
