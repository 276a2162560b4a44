#include "scene/DefaultLights.h"

#include "scene/DefaultCamera.h"

#include <algorithm>
#include <cmath>

namespace gi::scene {
namespace {

constexpr float kCeilingLightHeight = 0.9f;          // of the way from floor to ceiling
constexpr float kMinimumLightRise = 0.25f;           // of the room's height, above the centre
constexpr int kInsideCheckRays = 32;
constexpr float kSunElevation = glm::radians(50.0f);
constexpr float kSunTurn = glm::radians(30.0f);      // from the camera's azimuth, to its left

Light defaultLight(LightType type) {
    Light light;
    light.name = type == LightType::Directional ? "default sun" : "default light";
    light.type = type;
    light.color = glm::vec3(1.0f);
    light.isDefault = true;
    return light;
}

Light sun(const Aabb& framing, const glm::vec3& cameraEye) {
    const glm::vec3 toCamera = cameraEye - framing.center();
    const float cameraAzimuth = std::abs(toCamera.x) + std::abs(toCamera.z) > 0.0f
                                        ? std::atan2(toCamera.x, toCamera.z)
                                        : kObjectCameraAzimuth;
    const float azimuth = cameraAzimuth - kSunTurn;
    const glm::vec3 toSun(std::sin(azimuth) * std::cos(kSunElevation), std::sin(kSunElevation),
            std::cos(azimuth) * std::cos(kSunElevation));
    Light light = defaultLight(LightType::Directional);
    light.direction = -toSun;
    light.intensity = 1.0f;
    return light;
}

// True when more rays from `point` end on back faces than on front faces.
bool insideClosedObject(const glm::vec3& point, const Aabb& framing, const RayCaster& caster) {
    const float minDistance = surveyMinDistance(framing);
    const float maxDistance = 2.0f * glm::length(framing.size()) + minDistance;
    int front = 0, back = 0;
    for (const glm::vec3& direction : sphereDirections(kInsideCheckRays)) {
        if (const std::optional<RayHit> hit =
                        caster.cast(point, direction, minDistance, maxDistance)) {
            ++(hit->frontFace ? front : back);
        }
    }
    return back > front;
}

} // namespace

LightChoice chooseDefaultLights(const Aabb& framing, const SceneSurvey& survey,
        const RayCaster& caster, const glm::vec3& cameraEye) {
    LightChoice choice;
    const std::string kind = survey.describe();
    if (survey.kind == SceneKind::Interior) {
        const glm::vec3 centre = survey.centre;
        const float floorY = survey.floorBelow ? centre.y - *survey.floorBelow : framing.min.y;
        const float ceilingY =
                survey.ceilingAbove ? centre.y + *survey.ceilingAbove : framing.max.y;
        const float height = ceilingY - floorY;
        const float lightY = floorY + kCeilingLightHeight * height;
        const float rise = std::max(lightY - centre.y, kMinimumLightRise * height);
        Light light = defaultLight(LightType::Point);
        light.position = glm::vec3(centre.x, lightY, centre.z);
        light.direction = glm::vec3(0.0f, -1.0f, 0.0f);
        light.intensity = rise * rise;
        if (height > 0.0f && !insideClosedObject(light.position, framing, caster)) {
            choice.lights.push_back(light);
            choice.why = kind + " -> ceiling point light";
            return choice;
        }
        choice.lights.push_back(sun(framing, cameraEye));
        choice.why = kind + ", but the ceiling light's place is inside a closed object -> sun";
        return choice;
    }
    choice.lights.push_back(sun(framing, cameraEye));
    choice.why = kind + " -> sun from 50 deg elevation, beside the camera's azimuth";
    return choice;
}

} // namespace gi::scene
