// The one question the scene-defaults survey (scene/SceneSurvey.h) asks of the geometry: where
// does a ray first hit, and does it see that triangle's front? The scene layer states it; a
// ray tracer above it answers (reference/EmbreeRayCaster.h), so the rules stay testable here.
#pragma once

#include <glm/glm.hpp>

#include <optional>

namespace gi::scene {

struct RayHit {
    float distance = 0.0f;   // metres along the unit direction
    bool frontFace = false;  // the triangle winds counter-clockwise as seen from the origin
};

class RayCaster {
public:
    virtual ~RayCaster() = default;
    // The nearest hit along origin + t * direction (unit) for t in [minDistance, maxDistance];
    // nothing when the ray leaves without hitting. Cut-out texels of alpha-masked materials are
    // not hit. minDistance > 0 keeps a ray that starts on a surface from hitting it.
    [[nodiscard]] virtual std::optional<RayHit> cast(const glm::vec3& origin,
            const glm::vec3& direction, float minDistance, float maxDistance) const = 0;
};

// Stands in where no ray tracer is at hand: every ray escapes, so the survey finds an object
// or outdoor scene.
class NothingHitCaster : public RayCaster {
public:
    [[nodiscard]] std::optional<RayHit> cast(const glm::vec3&, const glm::vec3&, float,
            float) const override {
        return std::nullopt;
    }
};

} // namespace gi::scene
