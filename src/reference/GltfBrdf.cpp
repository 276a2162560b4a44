#include "reference/GltfBrdf.h"

#include "reference/SamplingMath.h"

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>

namespace gi::reference {
namespace {

constexpr float kDielectricF0 = 0.04f;   // glTF: index of refraction 1.5

glm::vec3 schlickFresnel(const glm::vec3& f0, float cosine) {
    const float m = 1.0f - std::clamp(cosine, 0.0f, 1.0f);
    const float m2 = m * m;
    return f0 + (glm::vec3(1.0f) - f0) * (m2 * m2 * m);
}

// D(h) with sin^2 from the cross product: 1 - cos^2 cancels catastrophically near the peak
// of a narrow lobe, where D is largest.
float ggxDistribution(float alpha, const glm::vec3& n, const glm::vec3& h) {
    const float a2 = alpha * alpha;
    const float cosH = glm::dot(n, h);
    const glm::vec3 side = glm::cross(n, h);
    const float d = glm::dot(side, side) + a2 * cosH * cosH;
    return a2 / (glm::pi<float>() * d * d);
}

// Smith's masking of one direction for GGX.
float smithG1(float alpha, float cosine) {
    const float a2 = alpha * alpha;
    return 2.0f * cosine / (cosine + std::sqrt(a2 + (1.0f - a2) * cosine * cosine));
}

// G2 / (4 n.l n.v), height-correlated (glTF specification, "V_GGX").
float smithVisibility(float alpha, float cosL, float cosV) {
    const float a2 = alpha * alpha;
    const float gv = cosL * std::sqrt(cosV * cosV * (1.0f - a2) + a2);
    const float gl = cosV * std::sqrt(cosL * cosL * (1.0f - a2) + a2);
    const float sum = gv + gl;
    return sum > 0.0f ? 0.5f / sum : 0.0f;
}

float mean(const glm::vec3& c) { return (c.x + c.y + c.z) / 3.0f; }

// Heitz 2018, listing 1, isotropic: a visible normal for view direction v in the local frame
// (z = the normal).
glm::vec3 sampleVisibleNormal(const glm::vec3& v, float alpha, float u1, float u2) {
    const glm::vec3 vh = glm::normalize(glm::vec3(alpha * v.x, alpha * v.y, v.z));
    const float lengthSquared = vh.x * vh.x + vh.y * vh.y;
    const glm::vec3 t1 = lengthSquared > 0.0f
                                 ? glm::vec3(-vh.y, vh.x, 0.0f) / std::sqrt(lengthSquared)
                                 : glm::vec3(1.0f, 0.0f, 0.0f);
    const glm::vec3 t2 = glm::cross(vh, t1);
    const float r = std::sqrt(u1);
    const float phi = glm::two_pi<float>() * u2;
    const float p1 = r * std::cos(phi);
    const float s = 0.5f * (1.0f + vh.z);
    const float p2 = (1.0f - s) * std::sqrt(std::max(0.0f, 1.0f - p1 * p1)) + s * r * std::sin(phi);
    const glm::vec3 nh =
            p1 * t1 + p2 * t2 + std::sqrt(std::max(0.0f, 1.0f - p1 * p1 - p2 * p2)) * vh;
    return glm::normalize(glm::vec3(alpha * nh.x, alpha * nh.y, std::max(0.0f, nh.z)));
}

} // namespace

GltfBrdf makeGltfBrdf(const glm::vec3& baseColor, float metallic, float roughness) {
    const float m = std::clamp(metallic, 0.0f, 1.0f);
    const float r = std::clamp(roughness, 0.0f, 1.0f);
    GltfBrdf brdf;
    brdf.diffuse = baseColor * (1.0f - m);
    brdf.f0 = glm::mix(glm::vec3(kDielectricF0), baseColor, m);
    brdf.alpha = std::max(r * r, kMinAlpha);
    return brdf;
}

glm::vec3 evaluateBrdf(const GltfBrdf& brdf, const glm::vec3& n, const glm::vec3& v,
        const glm::vec3& l) {
    const float cosV = glm::dot(n, v), cosL = glm::dot(n, l);
    if (!(cosV > 0.0f) || !(cosL > 0.0f)) return glm::vec3(0.0f);
    const glm::vec3 h = glm::normalize(v + l);
    const glm::vec3 fresnel = schlickFresnel(brdf.f0, glm::dot(v, h));
    const float specular =
            ggxDistribution(brdf.alpha, n, h) * smithVisibility(brdf.alpha, cosL, cosV);
    return (glm::vec3(1.0f) - fresnel) * brdf.diffuse * glm::one_over_pi<float>() +
           fresnel * specular;
}

float specularSamplingProbability(const GltfBrdf& brdf, const glm::vec3& n,
        const glm::vec3& v) {
    const float fresnel = mean(schlickFresnel(brdf.f0, glm::dot(n, v)));
    const float diffuse = mean(brdf.diffuse) * (1.0f - fresnel);
    const float sum = fresnel + diffuse;
    return sum > 0.0f ? fresnel / sum : 0.5f;
}

float brdfPdf(const GltfBrdf& brdf, const glm::vec3& n, const glm::vec3& v,
        const glm::vec3& l) {
    const float cosV = glm::dot(n, v);
    if (!(cosV > 0.0f)) return 0.0f;
    const float pSpecular = specularSamplingProbability(brdf, n, v);
    float pdf = (1.0f - pSpecular) * std::max(glm::dot(n, l), 0.0f) * glm::one_over_pi<float>();
    const glm::vec3 sum = v + l;
    const float length = glm::length(sum);
    if (length > 0.0f) {
        const glm::vec3 h = sum / length;
        const float cosH = glm::dot(n, h);
        if (cosH > 0.0f && glm::dot(v, h) > 0.0f) {
            pdf += pSpecular * smithG1(brdf.alpha, cosV) * ggxDistribution(brdf.alpha, n, h) /
                   (4.0f * cosV);
        }
    }
    return pdf;
}

bool sampleBrdf(const GltfBrdf& brdf, const glm::vec3& n, const glm::vec3& v,
        const float u[3], glm::vec3& l) {
    const float cosV = glm::dot(n, v);
    if (!(cosV > 0.0f)) return false;
    if (u[0] >= specularSamplingProbability(brdf, n, v)) {
        l = sampleCosineHemisphere(n, u[1], u[2]);
        return true;
    }
    glm::vec3 t, b;
    orthonormalBasis(n, t, b);
    const glm::vec3 local(glm::dot(v, t), glm::dot(v, b), cosV);
    const glm::vec3 m = sampleVisibleNormal(local, brdf.alpha, u[1], u[2]);
    const glm::vec3 h = glm::normalize(m.x * t + m.y * b + m.z * n);
    l = glm::normalize(2.0f * glm::dot(v, h) * h - v);
    return true;
}

} // namespace gi::reference
