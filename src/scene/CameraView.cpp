#include "scene/CameraView.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace gi::scene {
namespace {

// Far plane past the farthest bounds corner; near plane a fixed fraction of it, which keeps
// a 24/32-bit depth buffer precise over the whole scene.
void fitDepthRange(CameraView& camera, const scene::Aabb& bounds, float znear, float zfar) {
    float farthest = 1.0f;
    if (!bounds.empty()) {
        for (int i = 0; i < 8; ++i) {
            const glm::vec3 corner((i & 1) ? bounds.max.x : bounds.min.x,
                    (i & 2) ? bounds.max.y : bounds.min.y, (i & 4) ? bounds.max.z : bounds.min.z);
            farthest = std::max(farthest, glm::length(corner - camera.eye));
        }
        farthest = std::max(farthest, 1e-3f);
    }
    camera.zfar = zfar > 0.0f ? zfar : farthest * 1.05f;
    camera.znear = znear > 0.0f ? std::min(znear, camera.zfar * 0.5f) : camera.zfar * 1e-4f;
    camera.projection = glm::perspective(camera.yfov, camera.aspect, camera.znear, camera.zfar);
}

} // namespace

CameraView cameraFromScene(const scene::Camera& camera, float aspect, const scene::Aabb& bounds) {
    CameraView view;
    view.view = glm::inverse(camera.worldFromCamera);
    view.eye = glm::vec3(camera.worldFromCamera[3]);
    view.yfov = camera.yfov;
    view.aspect = aspect;
    fitDepthRange(view, bounds, camera.znear, camera.zfar);
    return view;
}

CameraView cameraLookAt(const glm::vec3& eye, const glm::vec3& target, float yfovRadians,
        float aspect, const scene::Aabb& bounds) {
    CameraView view;
    glm::vec3 forward = target - eye;
    if (glm::length(forward) < 1e-12f) forward = glm::vec3(0.0f, 0.0f, -1.0f);
    forward = glm::normalize(forward);
    const glm::vec3 up = std::abs(forward.y) > 0.999f ? glm::vec3(0.0f, 0.0f, -1.0f)
                                                      : glm::vec3(0.0f, 1.0f, 0.0f);
    view.view = glm::lookAt(eye, eye + forward, up);
    view.eye = eye;
    view.yfov = yfovRadians;
    view.aspect = aspect;
    fitDepthRange(view, bounds, 0.0f, 0.0f);
    return view;
}

namespace {

constexpr float kMovedDistanceShare = 0.05f;
constexpr float kMovedTurnCosine = 0.985f;   // about 10 degrees
constexpr float kMovedZoomRatio = 1.1f;

glm::vec3 forwardOf(const CameraView& camera) {
    return -glm::vec3(camera.view[0][2], camera.view[1][2], camera.view[2][2]);
}

} // namespace

bool viewMovedFarFrom(const CameraView& before, const CameraView& now, float sceneDiagonal) {
    const float zoom = now.yfov / std::max(before.yfov, 1e-6f);
    return glm::distance(before.eye, now.eye) > kMovedDistanceShare * sceneDiagonal ||
           glm::dot(glm::normalize(forwardOf(before)), glm::normalize(forwardOf(now))) <
                   kMovedTurnCosine ||
           zoom > kMovedZoomRatio || zoom < 1.0f / kMovedZoomRatio ||
           std::abs(now.aspect - before.aspect) > 0.01f * before.aspect;
}

} // namespace gi::scene
