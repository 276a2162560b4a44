#include "scene/Exposure.h"

#include <algorithm>
#include <cmath>

namespace gi::scene {

float characteristicIrradiance(const std::vector<Light>& lights, const Aabb& bounds,
        float maxEmission) {
    const glm::vec3 size = bounds.empty() ? glm::vec3(1.0f) : bounds.max - bounds.min;
    // In double: a 1e4 m scene squares to 1e8, and 1e7 cd / 1e-12 m^2 would overflow a float.
    const double diagonal = std::max(double(glm::length(size)), 1e-6);
    double peak = std::isfinite(maxEmission) ? std::max(0.0, double(maxEmission)) * M_PI : 0.0;
    for (const Light& light : lights) {
        const double power = lightStrength(light);
        if (!std::isfinite(power) || power <= 0.0) continue;
        peak = std::max(peak, isDistant(light.type) ? power : power / (diagonal * diagonal));
    }
    return float(std::min(peak, 1e38));
}

float preExposure(const std::vector<Light>& lights, const Aabb& bounds, float maxEmission) {
    const float peak = characteristicIrradiance(lights, bounds, maxEmission);
    if (!(peak > 0.0f)) return 1.0f;
    const int exponent = std::clamp(int(std::lround(-std::log2(double(peak)))), -64, 64);
    return std::ldexp(1.0f, exponent);
}

} // namespace gi::scene
