#include "scene/DefaultCamera.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

namespace gi::scene {
namespace {

constexpr float kObjectYfov = glm::radians(45.0f);
constexpr float kInteriorYfov = glm::radians(60.0f);
constexpr float kEyeHeight = 1.7f;              // metres above the floor
constexpr float kWallMarginFraction = 0.3f;     // of the free distance behind the centre
constexpr float kMinimumWallMargin = 0.5f;      // metres, unless that is over half the distance
constexpr float kFramingMargin = 1.05f;         // the bounds' corners stay 5% inside the view
constexpr float kMinimumSphereDistance = 1.1f;  // x the bounding sphere's radius
constexpr float kFlatFraction = 0.15f;          // thinnest side under this x the longest: flat
constexpr float kFlatViewTilt = glm::radians(20.0f);

Camera lookingFrom(const glm::vec3& eye, const glm::vec3& target, float yfov) {
    Camera camera;
    camera.name = "default camera";
    camera.worldFromCamera = glm::inverse(glm::lookAt(eye, target, glm::vec3(0.0f, 1.0f, 0.0f)));
    camera.yfov = yfov;
    camera.isDefault = true;
    return camera;
}

// The distance from the bounds' centre, along `towardEye`, at which every corner of the
// bounds lies inside a square view of field `yfov` (so in any wider output too).
float framingDistance(const Aabb& framing, const glm::vec3& towardEye, float yfov) {
    const glm::vec3 centre = framing.center();
    const glm::mat4 view = glm::lookAt(centre + towardEye, centre, glm::vec3(0.0f, 1.0f, 0.0f));
    const float tanHalf = std::tan(0.5f * yfov);
    float distance = 0.0f;
    for (int i = 0; i < 8; ++i) {
        const glm::vec3 corner((i & 1) ? framing.max.x : framing.min.x,
                (i & 2) ? framing.max.y : framing.min.y, (i & 4) ? framing.max.z : framing.min.z);
        // Camera space of a camera one unit from the centre: the corner is at depth -z - 1
        // from it; moving back to `d` adds d - 1.
        const glm::vec3 p = glm::vec3(view * glm::vec4(corner, 1.0f));
        const float offCentre = std::max(std::abs(p.x), std::abs(p.y));
        distance = std::max(distance, offCentre / tanHalf + p.z + 1.0f);
    }
    return kFramingMargin * distance;
}

// Which side of a flat scene's plane (normal +-`axis`) its triangles face: rays towards the
// plane from a 3x3 grid on the +axis side count front against back hits.
float frontSide(const Aabb& framing, int axis, const RayCaster& caster) {
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    const glm::vec3 size = framing.size();
    const float minDistance = surveyMinDistance(framing);
    const float reach = 2.0f * glm::length(size) + minDistance;
    glm::vec3 down(0.0f);
    down[axis] = -1.0f;
    int balance = 0;
    for (int i = 1; i <= 3; ++i) {
        for (int j = 1; j <= 3; ++j) {
            glm::vec3 origin = framing.min;
            origin[u] += 0.25f * float(i) * size[u];
            origin[v] += 0.25f * float(j) * size[v];
            origin[axis] = framing.max[axis] + glm::length(size);
            if (const std::optional<RayHit> hit = caster.cast(origin, down, minDistance, reach)) {
                balance += hit->frontFace ? 1 : -1;
            }
        }
    }
    return balance >= 0 ? 1.0f : -1.0f;
}

// The three-quarter view, or for a flat scene a view 20 degrees off its plane's normal, on
// the side its triangles face, leaning the way the three-quarter view does.
glm::vec3 objectViewDirection(const Aabb& framing, const RayCaster& caster, bool& flat) {
    const glm::vec3 threeQuarter(
            std::sin(kObjectCameraAzimuth) * std::cos(kObjectCameraElevation),
            std::sin(kObjectCameraElevation),
            std::cos(kObjectCameraAzimuth) * std::cos(kObjectCameraElevation));
    const glm::vec3 size = framing.size();
    const int thin = size.x <= size.y && size.x <= size.z ? 0 : (size.y <= size.z ? 1 : 2);
    flat = size[thin] < kFlatFraction * std::max({size.x, size.y, size.z});
    if (!flat) return threeQuarter;
    glm::vec3 normal(0.0f);
    normal[thin] = frontSide(framing, thin, caster);
    glm::vec3 along = threeQuarter;
    along[thin] = 0.0f;
    along = glm::normalize(along);
    return std::cos(kFlatViewTilt) * normal + std::sin(kFlatViewTilt) * along;
}

CameraChoice objectCamera(const Aabb& framing, const RayCaster& caster) {
    const glm::vec3 centre = framing.center();
    const float radius = 0.5f * glm::length(framing.size());
    bool flat = false;
    const glm::vec3 towardEye = objectViewDirection(framing, caster, flat);
    // Never inside the bounding sphere, so the near plane stays in front of the geometry.
    const float distance = std::max(framingDistance(framing, towardEye, kObjectYfov),
            kMinimumSphereDistance * radius);
    CameraChoice choice;
    choice.camera = lookingFrom(centre + distance * towardEye, centre, kObjectYfov);
    choice.camera.znear = std::max(1e-4f, 0.01f * (distance - radius));
    choice.camera.zfar = distance + 2.0f * radius;
    choice.why = flat ? "flat object -> framing the bounds from 20 deg off the side its "
                        "triangles face"
                      : "object -> framing the bounds from a three-quarter view (azimuth 45 "
                        "deg, elevation 25 deg)";
    return choice;
}

// Distance from `origin` (inside `box`) to where the ray leaves the box.
float exitDistance(const Aabb& box, const glm::vec3& origin, const glm::vec3& direction) {
    float distance = std::numeric_limits<float>::max();
    for (int axis = 0; axis < 3; ++axis) {
        if (direction[axis] > 0.0f) {
            distance = std::min(distance, (box.max[axis] - origin[axis]) / direction[axis]);
        } else if (direction[axis] < 0.0f) {
            distance = std::min(distance, (box.min[axis] - origin[axis]) / direction[axis]);
        }
    }
    return std::max(distance, 0.0f);
}

CameraChoice interiorCamera(const Aabb& framing, const SceneSurvey& survey,
        const RayCaster& caster) {
    const glm::vec3 centre = survey.centre;
    const float floorY = survey.floorBelow ? centre.y - *survey.floorBelow : framing.min.y;
    const float ceilingY = survey.ceilingAbove ? centre.y + *survey.ceilingAbove : framing.max.y;
    const float eyeHeight = std::min(kEyeHeight, 0.5f * (ceilingY - floorY));
    const glm::vec3 standing(centre.x, floorY + eyeHeight, centre.z);
    const float minDistance = surveyMinDistance(framing);
    const float maxDistance = 2.0f * glm::length(framing.size()) + minDistance;
    const auto freeDistance = [&](const glm::vec3& direction) {
        const std::optional<RayHit> hit =
                caster.cast(standing, direction, minDistance, maxDistance);
        return hit ? hit->distance : exitDistance(framing, standing, direction);
    };
    const float diagonal = std::sqrt(0.5f);
    const std::array<glm::vec3, 4> axes = {glm::vec3(0.0f, 0.0f, -1.0f),
            glm::vec3(1.0f, 0.0f, 0.0f), glm::vec3(diagonal, 0.0f, -diagonal),
            glm::vec3(diagonal, 0.0f, diagonal)};
    const std::array<const char*, 4> axisNames = {"z", "x", "the x-z diagonal", "the x+z diagonal"};
    std::size_t best = 0;
    float bestSpan = -1.0f;
    for (std::size_t i = 0; i < axes.size(); ++i) {
        // A small preference for the axes keeps a square room's view square to its walls.
        const float weight = i < 2 ? 1.0f : 0.95f;
        const float span = weight * (freeDistance(axes[i]) + freeDistance(-axes[i]));
        if (span > bestSpan) {
            best = i;
            bestSpan = span;
        }
    }
    // Look towards the nearer wall, stepping back towards the farther one: the camera then
    // sees the whole span in front of it.
    glm::vec3 look = axes[best];
    float behind = freeDistance(-look);
    const float ahead = freeDistance(look);
    if (ahead > behind) {
        look = -look;
        behind = ahead;
    }
    const float margin = std::min(std::max(kWallMarginFraction * behind, kMinimumWallMargin),
            0.5f * behind);
    const glm::vec3 eye = standing - (behind - margin) * look;
    CameraChoice choice;
    choice.camera = lookingFrom(eye, eye + look, kInteriorYfov);
    choice.camera.znear = std::max(1e-4f, 1e-4f * glm::length(framing.size()));
    choice.camera.zfar = 0.0f;
    char text[200];
    std::snprintf(text, sizeof text,
            "interior -> standing %.3g m above the floor under the centre, looking along %s "
            "(the longest free span, %.3g m), %.3g m before the wall behind",
            double(eyeHeight), axisNames[best], double(freeDistance(look) + behind),
            double(margin));
    choice.why = text;
    return choice;
}

} // namespace

CameraChoice chooseDefaultCamera(const Aabb& framing, const SceneSurvey& survey,
        const RayCaster& caster) {
    if (survey.kind == SceneKind::Interior) return interiorCamera(framing, survey, caster);
    return objectCamera(framing, caster);
}

} // namespace gi::scene
