// Answers the scene-defaults survey's rays (scene/RayCaster.h) with Embree, and adds a
// scene's missing defaults through it (scene/SceneDefaults.h).
#pragma once

#include "reference/EmbreeScene.h"
#include "scene/RayCaster.h"
#include "scene/SceneDefaults.h"

namespace gi::reference {

class EmbreeRayCaster : public scene::RayCaster {
public:
    explicit EmbreeRayCaster(const EmbreeState& state) : mState(state) {}
    [[nodiscard]] std::optional<scene::RayHit> cast(const glm::vec3& origin,
            const glm::vec3& direction, float minDistance, float maxDistance) const override;

private:
    const EmbreeState& mState;
};

// scene::addDefaults with rays cast by Embree; Embree's scene is built only when the scene
// lacks lights or cameras. If Embree cannot build it (out of memory), the survey sees no
// geometry and the scene gets the object defaults; `warning` then says why.
scene::DefaultsReport addDefaultsFromGeometry(scene::Scene& scene, std::string& warning);

// scene::defaultCamera with rays cast by Embree (the object camera if Embree fails).
[[nodiscard]] scene::Camera defaultCameraFromGeometry(const scene::Scene& scene);

} // namespace gi::reference
