#include "gi/atlas/AtlasMesh.h"

#include <cmath>

namespace gi::atlas {

AtlasMesh flattenScene(const scene::Scene& scene) {
    AtlasMesh mesh;
    mesh.positions.reserve(scene.vertexCount());
    mesh.indices.reserve(scene.triangleCount() * 3);
    bool allHaveTexcoord1 = true, anyTriangles = false;
    for (const scene::Instance& instance : scene.instances) {
        const scene::Primitive& primitive = scene.primitives[std::size_t(instance.primitive)];
        const glm::mat3 normalMatrix =
                glm::transpose(glm::inverse(glm::mat3(instance.worldFromLocal)));
        const bool doubleSided = primitive.material >= 0 &&
                scene.materials[std::size_t(primitive.material)].doubleSided;
        const auto base = std::uint32_t(mesh.positions.size());
        for (std::size_t i = 0; i < primitive.positions.size(); ++i) {
            mesh.positions.push_back(
                    glm::vec3(instance.worldFromLocal * glm::vec4(primitive.positions[i], 1.0f)));
            glm::vec3 n = normalMatrix * primitive.normals[i];
            const float length = glm::length(n);
            mesh.normals.push_back(length > 0.0f && std::isfinite(length)
                            ? n / length
                            : glm::vec3(0.0f, 1.0f, 0.0f));
            mesh.texcoords0.push_back(
                    i < primitive.texcoords0.size() ? primitive.texcoords0[i] : glm::vec2(0.0f));
            mesh.texcoords1.push_back(
                    i < primitive.texcoords1.size() ? primitive.texcoords1[i] : glm::vec2(0.0f));
            mesh.colors.push_back(
                    i < primitive.colors.size() ? primitive.colors[i] : glm::vec4(1.0f));
            mesh.doubleSided.push_back(doubleSided ? 1 : 0);
        }
        if (primitive.indices.size() >= 3) {
            anyTriangles = true;
            if (primitive.texcoords1.size() != primitive.positions.size()) allHaveTexcoord1 = false;
        }
        // GpuScene swaps two corners of mirrored instances; the atlas must wind the same way.
        for (std::size_t t = 0; t + 2 < primitive.indices.size(); t += 3) {
            const std::uint32_t a = primitive.indices[t], b = primitive.indices[t + 1],
                                c = primitive.indices[t + 2];
            mesh.indices.push_back(base + a);
            mesh.indices.push_back(base + (instance.flipWinding ? c : b));
            mesh.indices.push_back(base + (instance.flipWinding ? b : c));
        }
    }
    mesh.hasTexcoord1 = anyTriangles && allHaveTexcoord1;
    return mesh;
}

double triangleArea(const AtlasMesh& mesh, std::size_t t) {
    const glm::dvec3 a(mesh.positions[mesh.indices[3 * t]]);
    const glm::dvec3 b(mesh.positions[mesh.indices[3 * t + 1]]);
    const glm::dvec3 c(mesh.positions[mesh.indices[3 * t + 2]]);
    return 0.5 * glm::length(glm::cross(b - a, c - a));
}

} // namespace gi::atlas
