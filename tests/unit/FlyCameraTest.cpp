// The viewer's fly camera without a window: start pose taken from a camera, movement along the
// view axes at the scene-relative speed, Shift and wheel scaling, mouse look and its pitch
// limit, and the exact start view kept until the user moves.
#include "app/FlyCamera.h"

#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <cmath>

namespace gi::app {
namespace {

// Float math on metre-sized values: 1e-4 m is far below anything visible and far above the
// rounding of a handful of float operations.
constexpr float kEps = 1e-4f;

scene::Aabb unitCubeBounds(float size) {
    scene::Aabb bounds;
    bounds.extend(glm::vec3(0.0f));
    bounds.extend(glm::vec3(size));
    return bounds;
}

void expectNear(const glm::vec3& actual, const glm::vec3& expected, float eps = kEps) {
    EXPECT_NEAR(actual.x, expected.x, eps) << "x";
    EXPECT_NEAR(actual.y, expected.y, eps) << "y";
    EXPECT_NEAR(actual.z, expected.z, eps) << "z";
}

scene::CameraView lookAt(const glm::vec3& eye, const glm::vec3& target, const scene::Aabb& b) {
    return scene::cameraLookAt(eye, target, glm::radians(40.0f), 1.0f, b);
}

TEST(FlyCamera, StartsFromTheGivenCamera) {
    const scene::Aabb bounds = unitCubeBounds(2.0f);
    const FlyCamera camera(lookAt({1, 1, 5}, {1, 1, 0}, bounds), bounds);
    expectNear(camera.position(), {1, 1, 5});
    expectNear(camera.forward(), {0, 0, -1});
    expectNear(camera.right(), {1, 0, 0});
    EXPECT_NEAR(camera.yaw(), 0.0f, kEps);
    EXPECT_NEAR(camera.pitch(), 0.0f, kEps);
    EXPECT_NEAR(camera.yfov(), glm::radians(40.0f), kEps);

    const FlyCamera turned(lookAt({0, 0, 0}, {1, 1, 0}, bounds), bounds);
    expectNear(turned.forward(), glm::normalize(glm::vec3(1, 1, 0)));
    EXPECT_NEAR(turned.yaw(), glm::half_pi<float>(), kEps);
    EXPECT_NEAR(turned.pitch(), glm::quarter_pi<float>(), kEps);
}

TEST(FlyCamera, DefaultSpeedIsAQuarterDiagonalPerSecond) {
    const scene::Aabb bounds = unitCubeBounds(2.0f);
    const float diagonal = std::sqrt(12.0f);
    FlyCamera camera(lookAt({1, 1, 5}, {1, 1, 0}, bounds), bounds);
    EXPECT_NEAR(camera.speed(), 0.25f * diagonal, kEps);

    FlyInput input;
    input.forward = true;
    camera.update(input, 2.0f);
    expectNear(camera.position(), {1, 1, 5 - 0.5f * diagonal});
}

TEST(FlyCamera, EmptyBoundsStillMove) {
    const scene::Aabb empty;
    FlyCamera camera(lookAt({0, 0, 0}, {0, 0, -1}, empty), empty);
    EXPECT_GT(camera.speed(), 0.0f);
    EXPECT_TRUE(std::isfinite(camera.speed()));
}

TEST(FlyCamera, MovesAlongViewAxesAndWorldUp) {
    const scene::Aabb bounds = unitCubeBounds(4.0f);   // diagonal 4 sqrt 3: speed sqrt 3
    FlyCamera camera(lookAt({0, 0, 0}, {0, 0, -1}, bounds), bounds);
    const float speed = camera.speed();
    FlyInput input;
    input.right = true;
    camera.update(input, 1.0f);
    expectNear(camera.position(), {speed, 0, 0});
    input = {};
    input.up = true;
    camera.update(input, 1.0f);
    expectNear(camera.position(), {speed, speed, 0});
    input = {};
    input.down = true;
    input.left = true;
    camera.update(input, 1.0f);
    // Two axes at once move at the same speed, not sqrt 2 faster.
    const float step = speed / std::sqrt(2.0f);
    expectNear(camera.position(), {speed - step, speed - step, 0});
    input = {};
    input.forward = input.back = true;   // cancel out
    const glm::vec3 before = camera.position();
    camera.update(input, 1.0f);
    expectNear(camera.position(), before);
}

TEST(FlyCamera, ShiftIsFourTimesFaster) {
    const scene::Aabb bounds = unitCubeBounds(1.0f);
    FlyCamera camera(lookAt({0, 0, 0}, {0, 0, -1}, bounds), bounds);
    FlyInput input;
    input.back = true;
    input.fast = true;
    camera.update(input, 0.5f);
    expectNear(camera.position(), {0, 0, 0.5f * 4.0f * camera.speed()});
}

TEST(FlyCamera, WheelScalesSpeedWithinLimits) {
    const scene::Aabb bounds = unitCubeBounds(1.0f);
    FlyCamera camera(lookAt({0, 0, 0}, {0, 0, -1}, bounds), bounds);
    const float base = camera.speed();
    FlyInput input;
    input.scrollSteps = 2.0f;
    camera.update(input, 0.0f);
    EXPECT_NEAR(camera.speed(), base * 1.25f * 1.25f, base * 1e-5f);
    input.scrollSteps = -1000.0f;
    camera.update(input, 0.0f);
    EXPECT_NEAR(camera.speed(), base / FlyCamera::kMaxSpeedScale, base * 1e-5f);
    EXPECT_TRUE(camera.atStart()) << "changing speed does not move the camera";
}

TEST(FlyCamera, MouseLookTurnsAndClampsPitch) {
    const scene::Aabb bounds = unitCubeBounds(1.0f);
    FlyCamera camera(lookAt({0, 0, 0}, {0, 0, -1}, bounds), bounds);
    FlyInput input;
    input.mouseDelta = {100.0f, 0.0f};
    camera.update(input, 0.016f);
    EXPECT_NEAR(camera.yaw(), 0.0f, kEps) << "no turning unless a look button is held";
    input.look = true;
    camera.update(input, 0.016f);
    // Moving the mouse right turns right (towards +X when looking down -Z).
    EXPECT_NEAR(camera.yaw(), 100.0f * FlyCamera::kRadiansPerPixel, kEps);
    EXPECT_GT(camera.forward().x, 0.0f);
    EXPECT_FALSE(camera.atStart());

    input.mouseDelta = {0.0f, -1e6f};   // far up: pitch stops short of straight up
    camera.update(input, 0.016f);
    EXPECT_NEAR(camera.pitch(), FlyCamera::kMaxPitch, kEps);
    input.mouseDelta = {0.0f, 1e6f};
    camera.update(input, 0.016f);
    EXPECT_NEAR(camera.pitch(), -FlyCamera::kMaxPitch, kEps);
    const scene::CameraView view = camera.view(1.5f);
    for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 4; ++r) EXPECT_TRUE(std::isfinite(view.view[c][r]));
    }
}

TEST(FlyCamera, KeepsTheStartViewUntilMoved) {
    const scene::Aabb bounds = unitCubeBounds(3.0f);
    scene::Camera sceneCamera;
    // A rolled camera with its own clip planes: the fly camera cannot express roll, so the
    // first frames must use the scene camera's matrices unchanged.
    sceneCamera.worldFromCamera = glm::translate(glm::mat4(1.0f), glm::vec3(1, 2, 8)) *
                                  glm::rotate(glm::mat4(1.0f), 0.3f, glm::vec3(0, 0, 1));
    sceneCamera.yfov = 0.7f;
    sceneCamera.znear = 0.5f;
    sceneCamera.zfar = 40.0f;
    const scene::CameraView start = scene::cameraFromScene(sceneCamera, 1.0f, bounds);
    FlyCamera camera(start, bounds);
    FlyInput still;
    camera.update(still, 0.5f);
    const scene::CameraView view = camera.view(2.0f);
    EXPECT_TRUE(camera.atStart());
    EXPECT_EQ(view.view, start.view);
    EXPECT_FLOAT_EQ(view.aspect, 2.0f);
    EXPECT_FLOAT_EQ(view.znear, 0.5f);
    EXPECT_FLOAT_EQ(view.zfar, 40.0f);
    EXPECT_EQ(view.projection, glm::perspective(0.7f, 2.0f, 0.5f, 40.0f));

    FlyInput move;
    move.forward = true;
    camera.update(move, 0.1f);
    EXPECT_FALSE(camera.atStart());
    const scene::CameraView moved = camera.view(2.0f);
    EXPECT_FLOAT_EQ(moved.yfov, 0.7f);
    EXPECT_FLOAT_EQ(moved.aspect, 2.0f);
    expectNear(moved.eye, camera.position());
    EXPECT_LT(camera.position().z, 8.0f);

    camera.reset(start);
    EXPECT_TRUE(camera.atStart());
    expectNear(camera.position(), {1, 2, 8});
}

TEST(FlyCamera, StraightDownKeepsItsHeading) {
    const scene::Aabb bounds = unitCubeBounds(1.0f);
    scene::Camera sceneCamera;
    // Looking straight down (-Y) with the camera's up vector pointing to +X: heading +X.
    sceneCamera.worldFromCamera = glm::mat4(glm::vec4(0, 0, 1, 0), glm::vec4(1, 0, 0, 0),
            glm::vec4(0, 1, 0, 0), glm::vec4(0, 5, 0, 1));
    const FlyCamera camera(scene::cameraFromScene(sceneCamera, 1.0f, bounds), bounds);
    EXPECT_NEAR(camera.pitch(), -FlyCamera::kMaxPitch, kEps);
    EXPECT_NEAR(camera.yaw(), glm::half_pi<float>(), kEps);
}

} // namespace
} // namespace gi::app
