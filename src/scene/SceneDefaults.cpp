#include "scene/SceneDefaults.h"

#include "scene/DefaultCamera.h"
#include "scene/DefaultLights.h"
#include "scene/SceneSurvey.h"

#include <algorithm>
#include <cmath>

namespace gi::scene {
namespace {

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

DefaultsReport addDefaults(Scene& scene, const RayCaster& caster) {
    DefaultsReport report;
    if (!scene.lights.empty() && !scene.cameras.empty()) return report;
    const Aabb framing = defaultFramingBounds(scene);
    const SceneSurvey survey = surveyScene(framing, caster);
    if (scene.cameras.empty()) {
        const CameraChoice choice = chooseDefaultCamera(framing, survey, caster);
        scene.cameras.push_back(choice.camera);
        report.camera = "none in the file; " + choice.why;
    }
    if (scene.lights.empty()) {
        const glm::vec3 eye(scene.cameras.front().worldFromCamera[3]);
        LightChoice choice = chooseDefaultLights(framing, survey, caster, eye);
        scene.lights = std::move(choice.lights);
        report.lights = "none in the file; " + choice.why;
    }
    return report;
}

Camera defaultCamera(const Scene& scene, const RayCaster& caster) {
    const Aabb framing = defaultFramingBounds(scene);
    return chooseDefaultCamera(framing, surveyScene(framing, caster), caster).camera;
}

} // namespace gi::scene
