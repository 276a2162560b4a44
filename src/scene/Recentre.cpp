#include "scene/Recentre.h"

#include "scene/Animation.h"

#include <cmath>

namespace gi::scene {

bool isFarFromOrigin(const glm::vec3& centre, float size) {
    // At 16 scene sizes away a float still resolves a 2^-20 part of the scene (~1 um in a 1 m
    // box); beyond, the error grows with the distance. Nearer scenes keep their coordinates
    // so that what `info` prints and the user types match the file.
    const float distance = glm::length(centre);
    return std::isfinite(distance) && distance > 16.0f * std::max(size, 1e-3f);
}

glm::vec3 recentreFarScene(Scene& scene) {
    if (scene.bounds.empty()) return glm::vec3(0.0f);
    const glm::vec3 centre = 0.5f * (scene.bounds.min + scene.bounds.max);
    if (!isFarFromOrigin(centre, glm::length(scene.bounds.max - scene.bounds.min))) {
        return glm::vec3(0.0f);
    }
    const glm::vec3 origin(std::round(centre.x), std::round(centre.y), std::round(centre.z));
    Aabb bounds;
    for (Instance& instance : scene.instances) {
        instance.worldFromLocal[3] -= glm::vec4(origin, 0.0f);
        // Recomputed from the shifted transforms: the old bounds carry the far-away rounding.
        const Aabb& local = scene.primitives[std::size_t(instance.primitive)].localBounds;
        for (int i = 0; i < 8; ++i) {
            const glm::vec3 corner((i & 1) ? local.max.x : local.min.x,
                    (i & 2) ? local.max.y : local.min.y, (i & 4) ? local.max.z : local.min.z);
            bounds.extend(glm::vec3(instance.worldFromLocal * glm::vec4(corner, 1.0f)));
        }
    }
    scene.bounds = bounds;
    scene.origin = origin;   // animatedBounds and poseScene place dynamic instances relative to it
    scene.bounds = animatedBounds(scene);
    for (Light& light : scene.lights) light.position -= origin;
    for (Camera& camera : scene.cameras) camera.worldFromCamera[3] -= glm::vec4(origin, 0.0f);
    return origin;
}

} // namespace gi::scene
