// The camera a frame is rendered from: view and projection for a given output aspect ratio.
// glTF cameras keep their vertical field of view; the aspect ratio is the output's
// (DESIGN.md). Near and far planes come from the camera when given, otherwise from the
// scene bounds, so depth precision follows the scene's scale.
#pragma once

#include "scene/Scene.h"

#include <glm/glm.hpp>

namespace gi::scene {

struct CameraView {
    glm::mat4 view{1.0f};         // world -> camera (camera looks down -Z)
    glm::mat4 projection{1.0f};   // camera -> clip, OpenGL conventions
    glm::vec3 eye{0.0f};          // world-space position, metres
    float yfov = 0.8f;            // radians
    float aspect = 1.0f;          // width / height
    float znear = 0.01f, zfar = 100.0f;

    glm::mat4 viewProjection() const { return projection * view; }
};

[[nodiscard]] CameraView cameraFromScene(const scene::Camera& camera, float aspect,
        const scene::Aabb& bounds);
// Whether `now` moved further than 5 % of the scene's diagonal from `before`, turned about
// 10 degrees or zoomed 10 %: when work drawn for what one view sees (the VPLs' draw, the atlas
// senders' draw) is redone. Such a draw decides only where samples go, not what they carry, so
// one made for a nearby view stays unbiased; redoing it at every small move would pay for it
// each frame and make the samples jump between surfaces.
[[nodiscard]] bool viewMovedFarFrom(const CameraView& before, const CameraView& now,
        float sceneDiagonal);
[[nodiscard]] CameraView cameraLookAt(const glm::vec3& eye, const glm::vec3& target,
        float yfovRadians, float aspect, const scene::Aabb& bounds);

} // namespace gi::scene
