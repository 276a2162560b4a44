#include "scene/LightViews.h"

#include "scene/SunWindow.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace gi::scene {
namespace {

float farthestCorner(const glm::vec3& p, const Aabb& box) {
    float farthest = 0.0f;
    for (int i = 0; i < 8; ++i) {
        const glm::vec3 corner((i & 1) ? box.max.x : box.min.x, (i & 2) ? box.max.y : box.min.y,
                (i & 4) ? box.max.z : box.min.z);
        farthest = std::max(farthest, glm::length(corner - p));
    }
    return std::max(farthest * 1.01f, 1e-5f);
}

glm::vec3 upFor(const glm::vec3& direction) {
    return std::abs(direction.y) > 0.99f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
}

LightView directionalView(int index, const Light& light, const Aabb& region, float pixels) {
    const SunWindow window = sunWindow(light.direction, region);
    const glm::vec2 pixel = window.size / pixels;
    return {index, window.projection * window.view, light.direction, true, pixel.x * pixel.y,
            false};
}

} // namespace

std::vector<LightView> lightViews(const std::vector<Light>& lights, const Aabb& region,
        int resolution) {
    std::vector<LightView> views;
    if (region.empty()) return views;
    const float pixels = float(std::max(resolution, 1));
    for (std::size_t i = 0; i < lights.size(); ++i) {
        const Light& light = lights[i];
        const int index = int(i);
        if (light.type == LightType::Sky) continue;
        if (light.type == LightType::Directional) {
            views.push_back(directionalView(index, light, region, pixels));
            continue;
        }
        const float far = farthestCorner(light.position, region);
        const float near = far * 1e-4f;
        if (light.type == LightType::Spot) {
            const float fov = std::min(
                    2.0f * light.outerConeAngle + glm::radians(2.0f), glm::radians(170.0f));
            const glm::mat4 view = glm::lookAt(light.position, light.position + light.direction,
                    upFor(light.direction));
            const float pixel = 2.0f * std::tan(0.5f * fov) / pixels;
            views.push_back({index, glm::perspective(fov, 1.0f, near, far) * view,
                    light.direction, false, pixel * pixel, false});
            continue;
        }
        static const std::array<std::pair<glm::vec3, glm::vec3>, 6> faces = {{
                {{1, 0, 0}, {0, -1, 0}}, {{-1, 0, 0}, {0, -1, 0}}, {{0, 1, 0}, {0, 0, 1}},
                {{0, -1, 0}, {0, 0, -1}}, {{0, 0, 1}, {0, -1, 0}}, {{0, 0, -1}, {0, -1, 0}}}};
        const glm::mat4 projection = glm::perspective(glm::radians(90.0f), 1.0f, near, far);
        const float pixel = 2.0f / pixels;   // tan(45 deg) = 1
        for (const auto& [direction, up] : faces) {
            views.push_back({index,
                    projection * glm::lookAt(light.position, light.position + direction, up),
                    direction, false, pixel * pixel, light.type == LightType::Area});
        }
    }
    return views;
}

} // namespace gi::scene
