#include "reference/LightSampling.h"

#include "reference/SamplingMath.h"

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace gi::reference {
namespace {

// Unit vector along v; false when v is zero or not finite (a light without a direction).
bool normalized(const glm::vec3& v, glm::vec3& unit) {
    const float length = glm::length(v);
    if (!(length > 0.0f) || !std::isfinite(length)) return false;
    unit = v / length;
    return true;
}

} // namespace

bool usableLight(const scene::Light& light, const glm::vec3& radiant) {
    if (light.type == scene::LightType::Area) {
        return std::any_of(light.emitters.begin(), light.emitters.end(),
                [](const scene::EmitterTriangle& t) {
                    return isFinite(t.radiance) && maxComponent(t.radiance) > 0.0f &&
                           isFinite(t.p0) && isFinite(t.p1) && isFinite(t.p2);
                });
    }
    const bool positioned = light.type == scene::LightType::Sky || isFinite(light.position);
    return isFinite(radiant) && positioned && maxComponent(radiant) > 0.0f;
}

float emissionPdf(const scene::Light& light) {
    glm::vec3 axis;
    if (light.type == scene::LightType::Point) return 1.0f / (4.0f * glm::pi<float>());
    if (light.type == scene::LightType::Spot && normalized(light.direction, axis)) {
        const float solidAngle = glm::two_pi<float>() *
                (1.0f - std::cos(std::clamp(light.outerConeAngle, 0.0f, glm::pi<float>())));
        return solidAngle > 1e-6f ? 1.0f / solidAngle : 0.0f;
    }
    return 0.0f;
}

glm::vec3 lightSubpathDirection(const scene::Light& light, float u1, float u2) {
    float cosTheta = 1.0f - 2.0f * u1;
    glm::vec3 axis(0.0f, 0.0f, 1.0f);
    if (light.type == scene::LightType::Spot) {
        const float cosOuter = std::cos(std::clamp(light.outerConeAngle, 0.0f, glm::pi<float>()));
        cosTheta = 1.0f - u1 * (1.0f - cosOuter);
        axis = glm::normalize(light.direction);   // non-zero: emissionPdf > 0
    }
    const float sinTheta = std::sqrt(std::max(0.0f, 1.0f - cosTheta * cosTheta));
    const float phi = glm::two_pi<float>() * u2;
    glm::vec3 t, b;
    orthonormalBasis(axis, t, b);
    return glm::normalize(sinTheta * std::cos(phi) * t + sinTheta * std::sin(phi) * b +
                          cosTheta * axis);
}

bool lightGeometry(const scene::Light& light, const glm::vec3& p, glm::vec3& wi,
        float& distance, float& factor) {
    glm::vec3 axis(0.0f);
    if (light.type != scene::LightType::Point && !normalized(light.direction, axis)) return false;
    if (light.type == scene::LightType::Directional) {
        wi = -axis;
        distance = std::numeric_limits<float>::infinity();
        factor = 1.0f;
        return true;
    }
    const glm::vec3 toLight = light.position - p;
    const float distance2 = glm::dot(toLight, toLight);
    if (!(distance2 > 0.0f) || !std::isfinite(distance2)) return false;
    distance = std::sqrt(distance2);
    wi = toLight / distance;
    factor = 1.0f / distance2;
    if (light.type == scene::LightType::Spot) {
        const float cosAlpha = glm::dot(axis, -wi);
        const float cosOuter = std::cos(light.outerConeAngle);
        const float cosInner = std::cos(light.innerConeAngle);
        float s = 0.0f;
        if (cosInner > cosOuter) {
            s = std::clamp((cosAlpha - cosOuter) / (cosInner - cosOuter), 0.0f, 1.0f);
        } else {
            s = cosAlpha >= cosOuter ? 1.0f : 0.0f;
        }
        factor *= s * s;
    }
    return factor > 0.0f && std::isfinite(factor);
}

} // namespace gi::reference
