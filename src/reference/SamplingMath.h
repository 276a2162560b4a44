// Small vector helpers the path tracer and its light sampling share: component maxima and
// finiteness, an orthonormal basis around a direction, and cosine-weighted hemisphere sampling.
#pragma once

#include <glm/glm.hpp>
#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>

namespace gi::reference {

inline float maxAbs(const glm::vec3& v) {
    return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
}

inline float maxComponent(const glm::vec3& v) { return std::max({v.x, v.y, v.z}); }

inline bool isFinite(const glm::vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// Orthonormal basis around a unit vector (Duff et al., "Building an Orthonormal Basis,
// Revisited", JCGT 6(1), 2017).
inline void orthonormalBasis(const glm::vec3& n, glm::vec3& t, glm::vec3& b) {
    const float sign = std::copysign(1.0f, n.z);
    const float a = -1.0f / (sign + n.z);
    const float c = n.x * n.y * a;
    t = glm::vec3(1.0f + sign * n.x * n.x * a, sign * c, -sign * n.x);
    b = glm::vec3(c, sign + n.y * n.y * a, -n.y);
}

// Cosine-weighted direction about n (Malley's method, PBRT 3rd ed. 13.6.3): pdf = cos/pi.
inline glm::vec3 sampleCosineHemisphere(const glm::vec3& n, float u1, float u2) {
    const float r = std::sqrt(u1);
    const float phi = glm::two_pi<float>() * u2;
    glm::vec3 t, b;
    orthonormalBasis(n, t, b);
    const float z = std::sqrt(std::max(0.0f, 1.0f - u1));
    return glm::normalize(r * std::cos(phi) * t + r * std::sin(phi) * b + z * n);
}
} // namespace gi::reference
