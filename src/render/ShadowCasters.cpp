#include "render/ShadowCasters.h"

#include <bit>
#include <cmath>
#include <utility>

namespace gi::render {

std::vector<glm::vec4> shadowCasterCorners(const scene::Scene& scene) {
    std::vector<glm::vec4> corners;
    int triangle = -1;   // in the scene's flattened order, degenerate triangles counted
    for (std::size_t i = 0; i < scene.instances.size(); ++i) {
        const scene::Instance& instance = scene.instances[i];
        const scene::Primitive& primitive = scene.primitives[std::size_t(instance.primitive)];
        for (std::size_t t = 0; t + 2 < primitive.indices.size(); t += 3) {
            ++triangle;
            glm::vec3 p[3];
            for (int k = 0; k < 3; ++k) {
                p[k] = glm::vec3(instance.worldFromLocal *
                                 glm::vec4(primitive.positions[primitive.indices[t + std::size_t(k)]], 1.0f));
            }
            const float area = glm::length(glm::cross(p[1] - p[0], p[2] - p[0]));
            if (!(area > 0.0f) || !std::isfinite(area)) continue;
            // Wound as the atlas winds it (atlas::flattenScene), so corner k is the atlas
            // triangle's corner k; a ray meets a triangle from either side.
            if (instance.flipWinding) std::swap(p[1], p[2]);
            const float index = std::bit_cast<float>(triangle);
            for (const glm::vec3& corner : p) corners.push_back(glm::vec4(corner, index));
        }
    }
    return corners;
}

} // namespace gi::render
