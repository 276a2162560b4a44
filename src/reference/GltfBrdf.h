// The glTF 2.0 metallic-roughness BRDF (glTF 2.0 specification, Appendix B "BRDF
// Implementation"), the path tracer's glossy material model (material.model=gltf):
//   f(v, l) = (1 - F) c_diff / pi + F D G / (4 |n.l| |n.v|),
//   c_diff = baseColor (1 - metallic),  F = F0 + (1 - F0) (1 - |v.h|)^5,
//   F0 = mix(0.04, baseColor, metallic),  alpha = roughness^2,
// with the GGX (Trowbridge-Reitz) distribution D and the height-correlated Smith masking-
// shadowing G (Heitz 2014, "Understanding the Masking-Shadowing Function"). Every factor is
// symmetric in v and l, so f is reciprocal. shaders/common/brdf.glsl is the same BRDF on the
// GPU.
//
// Importance sampling: with probability pSpecular a half vector from the GGX distribution of
// visible normals (Heitz 2018, "Sampling the GGX Distribution of Visible Normals", JCGT 7(4)),
// reflected about it, otherwise a cosine-weighted direction. pSpecular depends on v only, so
// pdf() is the mixture's exact density: pSpecular G1(v) D(h) / (4 n.v) + (1 - pSpecular)
// cos/pi. Directions below the surface carry density too (the VNDF sample can reflect under
// the horizon): the caller drops them, f = 0 there.
#pragma once

#include <glm/glm.hpp>

namespace gi::reference {

struct GltfBrdf {
    glm::vec3 diffuse{0.0f};   // c_diff
    glm::vec3 f0{0.04f};       // Fresnel reflectance at normal incidence
    float alpha = 1.0f;        // GGX width: perceptual roughness squared, kept >= kMinAlpha
};

// Roughness 0 would make D a delta that no finite sample finds: clamp alpha to a
// near-mirror (roughness ~0.03).
constexpr float kMinAlpha = 1e-3f;

[[nodiscard]] GltfBrdf makeGltfBrdf(const glm::vec3& baseColor, float metallic,
        float roughness);

// f(v, l) for unit vectors with v and l on n's side (0 otherwise).
[[nodiscard]] glm::vec3 evaluateBrdf(const GltfBrdf& brdf, const glm::vec3& n,
        const glm::vec3& v, const glm::vec3& l);

// Probability of choosing the specular lobe for viewer direction v.
[[nodiscard]] float specularSamplingProbability(const GltfBrdf& brdf, const glm::vec3& n,
        const glm::vec3& v);

// Solid-angle density with which sampleBrdf() returns l, for any unit l.
[[nodiscard]] float brdfPdf(const GltfBrdf& brdf, const glm::vec3& n, const glm::vec3& v,
        const glm::vec3& l);

// A direction l from three uniform numbers (u[0] picks the lobe); false when v is below the
// surface. l may lie below the surface (f = 0 there).
[[nodiscard]] bool sampleBrdf(const GltfBrdf& brdf, const glm::vec3& n, const glm::vec3& v,
        const float u[3], glm::vec3& l);

} // namespace gi::reference
