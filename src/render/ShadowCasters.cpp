#include "render/ShadowCasters.h"

#include <cmath>

namespace gi::render {

std::vector<glm::vec4> shadowCasterCorners(const scene::Scene& scene) {
    std::vector<glm::vec4> corners;
    for (std::size_t i = 0; i < scene.instances.size(); ++i) {
        const scene::Instance& instance = scene.instances[i];
        const scene::Primitive& primitive = scene.primitives[std::size_t(instance.primitive)];
        for (std::size_t t = 0; t + 2 < primitive.indices.size(); t += 3) {
            glm::vec3 p[3];
            for (int k = 0; k < 3; ++k) {
                p[k] = glm::vec3(instance.worldFromLocal *
                                 glm::vec4(primitive.positions[primitive.indices[t + std::size_t(k)]], 1.0f));
            }
            const float area = glm::length(glm::cross(p[1] - p[0], p[2] - p[0]));
            if (!(area > 0.0f) || !std::isfinite(area)) continue;
            for (const glm::vec3& corner : p) corners.push_back(glm::vec4(corner, 0.0f));
        }
    }
    return corners;
}

} // namespace gi::render
