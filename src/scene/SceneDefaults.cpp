#include "scene/SceneDefaults.h"

#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace gi::scene {
namespace {

constexpr float kDefaultYfov = glm::radians(45.0f);
constexpr float kCameraElevation = glm::radians(15.0f);
// Degenerate bounds are padded so the camera never sits on its target in float arithmetic.
constexpr float kMinimumSize = 1e-6f;         // metres
constexpr float kMinimumRelativeSize = 1e-6f; // of the bounds' distance from the origin

} // namespace

Aabb defaultFramingBounds(const Scene& scene) {
    const Aabb& b = scene.bounds;
    auto finite = [](const glm::vec3& v) {
        return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
    };
    Aabb framing;
    if (b.empty() || !finite(b.min) || !finite(b.max) || !std::isfinite(glm::length(b.size()))) {
        framing.extend(glm::vec3(-0.5f));
        framing.extend(glm::vec3(0.5f));
        return framing;
    }
    const glm::vec3 centre = 0.5f * b.min + 0.5f * b.max;
    const float distance = std::max({std::abs(centre.x), std::abs(centre.y), std::abs(centre.z)});
    const float minimumSize = std::max(kMinimumRelativeSize * distance, kMinimumSize);
    if (glm::length(b.size()) >= minimumSize) return b;
    framing.extend(centre - glm::vec3(0.5f * minimumSize));
    framing.extend(centre + glm::vec3(0.5f * minimumSize));
    return framing;
}

void addDefaults(Scene& scene) {
    const Aabb bounds = defaultFramingBounds(scene);
    const glm::vec3 centre = 0.5f * bounds.min + 0.5f * bounds.max;
    const glm::vec3 size = bounds.size();
    const float extent = std::max({size.x, size.y, size.z});

    if (scene.lights.empty()) {
        const float height = size.y >= 0.05f * extent ? 0.4f * size.y : 0.25f * extent;
        Light light;
        light.name = "default light";
        light.type = LightType::Point;
        light.position = centre + glm::vec3(0.0f, height, 0.0f);
        light.direction = glm::vec3(0.0f, -1.0f, 0.0f);
        light.color = glm::vec3(1.0f);
        light.intensity = height * height;
        light.isDefault = true;
        scene.lights.push_back(light);
    }

    if (scene.cameras.empty()) {
        const float radius = 0.5f * glm::length(size);
        const float distance = radius / std::sin(0.5f * kDefaultYfov);
        const glm::vec3 towardEye(0.0f, std::sin(kCameraElevation), std::cos(kCameraElevation));
        const glm::vec3 eye = centre + distance * towardEye;
        Camera camera;
        camera.name = "default camera";
        camera.worldFromCamera =
                glm::inverse(glm::lookAt(eye, centre, glm::vec3(0.0f, 1.0f, 0.0f)));
        camera.yfov = kDefaultYfov;
        camera.znear = std::max(1e-4f, 0.01f * distance);
        camera.zfar = distance + 2.0f * radius;
        camera.isDefault = true;
        scene.cameras.push_back(camera);
    }
}

} // namespace gi::scene
