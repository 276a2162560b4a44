#include "scene/Scene.h"

#include <algorithm>
#include <cmath>

namespace gi::scene {

glm::vec3 EmitterTriangle::normal() const {
    const glm::vec3 n = glm::cross(p1 - p0, p2 - p0);
    const float length = glm::length(n);
    return length > 0.0f && std::isfinite(length) ? n / length : glm::vec3(0.0f);
}

float EmitterTriangle::area() const {
    return 0.5f * glm::length(glm::cross(p1 - p0, p2 - p0));
}

double lightStrength(const Light& light) {
    auto largest = [](const glm::vec3& c) { return double(std::max({c.x, c.y, c.z})); };
    if (light.type == LightType::Area) {
        double sum = 0.0;
        for (const EmitterTriangle& t : light.emitters) {
            sum += largest(t.radiance) * double(t.area()) * (t.twoSided ? 2.0 : 1.0);
        }
        return sum;
    }
    const double strength = largest(light.color) * double(light.intensity);
    return light.type == LightType::Sky ? M_PI * strength : strength;
}

glm::vec3 skyRadiance(const std::vector<Light>& lights) {
    glm::vec3 sum(0.0f);
    for (const Light& light : lights) {
        if (light.type == LightType::Sky) sum += light.color * light.intensity;
    }
    return sum;
}

std::size_t Scene::triangleCount() const {
    std::size_t n = 0;
    for (const Instance& instance : instances) n += primitives[instance.primitive].indices.size() / 3;
    return n;
}

std::size_t Scene::vertexCount() const {
    std::size_t n = 0;
    for (const Instance& instance : instances) n += primitives[instance.primitive].positions.size();
    return n;
}

} // namespace gi::scene
