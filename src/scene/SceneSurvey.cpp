#include "scene/SceneSurvey.h"

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace gi::scene {
namespace {

constexpr float kRelativeMinDistance = 1e-5f;   // of the bounds' diagonal
constexpr float kMinimumMinDistance = 1e-6f;    // metres
constexpr float kPointOffset = 0.25f;           // of the bounds' width / depth

std::string percent(float fraction) {
    char text[16];
    std::snprintf(text, sizeof text, "%.0f%%", 100.0 * double(fraction));
    return text;
}

} // namespace

std::string SceneSurvey::describe() const {
    const std::string front = percent(frontFraction()) + " of survey rays hit front faces";
    if (kind == SceneKind::Interior) return "interior (" + front + ")";
    return "object or outdoor scene (" + front + ", " + percent(backFraction()) +
           " back faces, " + percent(escapeFraction()) + " escape)";
}

float surveyMinDistance(const Aabb& bounds) {
    return std::max(kRelativeMinDistance * glm::length(bounds.size()), kMinimumMinDistance);
}

std::vector<glm::vec3> sphereDirections(int count) {
    std::vector<glm::vec3> directions;
    directions.reserve(std::size_t(std::max(count, 0)));
    const float goldenAngle = glm::pi<float>() * (3.0f - std::sqrt(5.0f));
    for (int i = 0; i < count; ++i) {
        const float y = 1.0f - (2.0f * float(i) + 1.0f) / float(count);
        const float radius = std::sqrt(std::max(0.0f, 1.0f - y * y));
        const float phi = goldenAngle * float(i);
        directions.emplace_back(radius * std::cos(phi), y, radius * std::sin(phi));
    }
    return directions;
}

SceneSurvey surveyScene(const Aabb& bounds, const RayCaster& caster) {
    SceneSurvey survey;
    survey.centre = bounds.center();
    const glm::vec3 size = bounds.size();
    const float minDistance = surveyMinDistance(bounds);
    // Twice the diagonal reaches past the bounds from any point inside them.
    const float maxDistance = 2.0f * glm::length(size) + minDistance;
    const glm::vec3 points[SceneSurvey::kPoints] = {survey.centre,
            survey.centre + glm::vec3(kPointOffset * size.x, 0.0f, 0.0f),
            survey.centre - glm::vec3(kPointOffset * size.x, 0.0f, 0.0f),
            survey.centre + glm::vec3(0.0f, 0.0f, kPointOffset * size.z),
            survey.centre - glm::vec3(0.0f, 0.0f, kPointOffset * size.z)};
    const std::vector<glm::vec3> directions = sphereDirections(SceneSurvey::kRaysPerPoint);
    for (const glm::vec3& point : points) {
        for (const glm::vec3& direction : directions) {
            ++survey.rays;
            const std::optional<RayHit> hit =
                    caster.cast(point, direction, minDistance, maxDistance);
            if (!hit) continue;
            ++(hit->frontFace ? survey.frontHits : survey.backHits);
        }
    }
    survey.kind = survey.frontFraction() >= SceneSurvey::kInteriorFrontFraction
                          ? SceneKind::Interior
                          : SceneKind::Object;
    const auto distance = [&](glm::vec3 direction) -> std::optional<float> {
        const std::optional<RayHit> hit =
                caster.cast(survey.centre, direction, minDistance, maxDistance);
        return hit ? std::optional<float>(hit->distance) : std::nullopt;
    };
    survey.floorBelow = distance({0.0f, -1.0f, 0.0f});
    survey.ceilingAbove = distance({0.0f, 1.0f, 0.0f});
    return survey;
}

} // namespace gi::scene
