// Scenes built in code for the reference-renderer tests (quads, a closed box, an emitter over a
// receiver), and the camera-ray geometry the analytic expectations are computed with: a
// pixel (x, y) covers [x, x+1) x [y, y+1) in image coordinates, rows top to bottom, and its
// ray runs from the near plane through the unprojected point (DESIGN.md: a pixel's value is
// the mean radiance over its square).
#pragma once

#include "scene/CameraView.h"
#include "scene/Scene.h"

#include <glm/glm.hpp>

#include <array>

namespace gi::test {

inline int addMaterial(scene::Scene& scene, const glm::vec3& albedo,
        const glm::vec3& emission = glm::vec3(0.0f)) {
    scene::Material material;
    material.baseColorFactor = glm::vec4(albedo, 1.0f);
    material.emissiveFactor = emission;
    scene.materials.push_back(material);
    return int(scene.materials.size()) - 1;
}

// A planar quad; corners counter-clockwise seen from the side its normal faces.
inline void addQuad(scene::Scene& scene, const std::array<glm::vec3, 4>& corners, int material,
        const glm::mat4& worldFromLocal = glm::mat4(1.0f)) {
    scene::Primitive primitive;
    const glm::vec3 normal =
            glm::normalize(glm::cross(corners[1] - corners[0], corners[2] - corners[0]));
    for (const glm::vec3& corner : corners) {
        primitive.positions.push_back(corner);
        primitive.normals.push_back(normal);
        primitive.localBounds.extend(corner);
    }
    primitive.indices = {0, 1, 2, 0, 2, 3};
    primitive.material = material;
    scene.primitives.push_back(primitive);
    scene::Instance instance;
    instance.primitive = int(scene.primitives.size()) - 1;
    instance.worldFromLocal = worldFromLocal;
    scene.instances.push_back(instance);
    for (const glm::vec3& corner : corners) {
        scene.bounds.extend(glm::vec3(worldFromLocal * glm::vec4(corner, 1.0f)));
    }
}

// The cube [-s, s]^3 as six quads facing inwards, all with one material.
inline scene::Scene closedBox(const glm::vec3& albedo, const glm::vec3& emission, float s) {
    scene::Scene scene;
    const int material = addMaterial(scene, albedo, emission);
    const glm::vec3 c[8] = {{-s, -s, -s}, {s, -s, -s}, {s, s, -s}, {-s, s, -s},
            {-s, -s, s}, {s, -s, s}, {s, s, s}, {-s, s, s}};
    addQuad(scene, {c[0], c[1], c[2], c[3]}, material);   // back (z = -s), faces +z
    addQuad(scene, {c[5], c[4], c[7], c[6]}, material);   // front (z = +s), faces -z
    addQuad(scene, {c[4], c[0], c[3], c[7]}, material);   // left (x = -s), faces +x
    addQuad(scene, {c[1], c[5], c[6], c[2]}, material);   // right (x = +s), faces -x
    addQuad(scene, {c[4], c[5], c[1], c[0]}, material);   // floor (y = -s), faces +y
    addQuad(scene, {c[3], c[2], c[6], c[7]}, material);   // ceiling (y = +s), faces -y
    return scene;
}

struct PixelRay {
    glm::dvec3 origin;
    glm::dvec3 direction;   // unit
};

// The ray through image point (x, y), x in [0, width), y in [0, height) from the top.
inline PixelRay pixelRay(const scene::CameraView& camera, int width, int height, double x,
        double y) {
    const glm::dmat4 clipToWorld =
            glm::inverse(glm::dmat4(camera.projection) * glm::dmat4(camera.view));
    const double ndcX = 2.0 * x / double(width) - 1.0;
    const double ndcY = 1.0 - 2.0 * y / double(height);
    const glm::dvec4 nearH = clipToWorld * glm::dvec4(ndcX, ndcY, -1.0, 1.0);
    const glm::dvec4 farH = clipToWorld * glm::dvec4(ndcX, ndcY, 1.0, 1.0);
    const glm::dvec3 nearP = glm::dvec3(nearH) / nearH.w;
    const glm::dvec3 farP = glm::dvec3(farH) / farH.w;
    return {nearP, glm::normalize(farP - nearP)};
}

// Where the ray meets the plane y = height; false when it runs parallel or away from it.
inline bool hitPlaneY(const PixelRay& ray, double planeY, glm::dvec3& point) {
    if (std::abs(ray.direction.y) < 1e-12) return false;
    const double t = (planeY - ray.origin.y) / ray.direction.y;
    if (!(t > 0.0)) return false;
    point = ray.origin + t * ray.direction;
    return true;
}

} // namespace gi::test
