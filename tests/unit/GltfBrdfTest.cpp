// The path tracer's glTF metallic-roughness BRDF (reference/GltfBrdf.h): energy (a white
// metal in a white furnace reflects at most all, and little less when moderately rough),
// reciprocity, a sampling density that integrates to one, and sampling that agrees with it.
#include "reference/GltfBrdf.h"

#include "reference/Pcg32.h"

#include <gtest/gtest.h>

#include <glm/gtc/constants.hpp>

#include <cmath>

namespace gi::reference {
namespace {

const glm::vec3 kNormal(0.0f, 0.0f, 1.0f);

glm::vec3 viewAt(float cosTheta) {
    return glm::vec3(std::sqrt(1.0f - cosTheta * cosTheta), 0.0f, cosTheta);
}

glm::vec3 uniformSphere(float u1, float u2) {
    const float z = 1.0f - 2.0f * u1;
    const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
    const float phi = glm::two_pi<float>() * u2;
    return glm::vec3(r * std::cos(phi), r * std::sin(phi), z);
}

// Directional albedo: the integral of f cos over the upper hemisphere, estimated with the
// BRDF's own sampling (f cos / pdf).
double sampledAlbedo(const GltfBrdf& brdf, const glm::vec3& v, int samples, std::uint64_t seed) {
    Pcg32 rng(seed, 1);
    double sum = 0.0;
    for (int i = 0; i < samples; ++i) {
        const float u[3] = {rng.nextFloat(), rng.nextFloat(), rng.nextFloat()};
        glm::vec3 l;
        if (!sampleBrdf(brdf, kNormal, v, u, l)) continue;
        const float cosL = glm::dot(kNormal, l);
        const float pdf = brdfPdf(brdf, kNormal, v, l);
        if (cosL <= 0.0f || !(pdf > 0.0f)) continue;
        sum += double(evaluateBrdf(brdf, kNormal, v, l).g) * cosL / pdf;
    }
    return sum / samples;
}

// The same integral with uniformly sampled directions (pdf 1/(2 pi)), which knows nothing of
// the BRDF's sampling.
double uniformAlbedo(const GltfBrdf& brdf, const glm::vec3& v, int samples, std::uint64_t seed) {
    Pcg32 rng(seed, 2);
    double sum = 0.0;
    for (int i = 0; i < samples; ++i) {
        glm::vec3 l = uniformSphere(rng.nextFloat(), rng.nextFloat());
        l.z = std::abs(l.z);
        sum += double(evaluateBrdf(brdf, kNormal, v, l).g) * l.z;
    }
    return sum / samples * glm::two_pi<double>();
}

TEST(GltfBrdf, WhiteMetalFurnaceReflectsAtMostAllAndMostWhenModeratelyRough) {
    for (float roughness : {0.05f, 0.3f, 0.5f, 0.7f, 1.0f}) {
        const GltfBrdf brdf = makeGltfBrdf(glm::vec3(1.0f), 1.0f, roughness);
        for (float cosV : {0.2f, 0.5f, 0.9f, 1.0f}) {
            const double albedo = sampledAlbedo(brdf, viewAt(cosV), 200000, 7);
            EXPECT_LE(albedo, 1.005) << "roughness " << roughness << ", cos " << cosV;
            if (roughness <= 0.5f && cosV >= 0.5f) {
                // Single-scattering GGX loses the light that would scatter between microfacets:
                // about 13% at roughness 0.5 (Kulla and Conty 2017), less when smoother.
                EXPECT_GE(albedo, 0.8) << "roughness " << roughness << ", cos " << cosV;
            }
        }
    }
}

TEST(GltfBrdf, DielectricReflectsLessThanItsBaseColourPlusFresnel) {
    const GltfBrdf brdf = makeGltfBrdf(glm::vec3(0.8f), 0.0f, 0.6f);
    for (float cosV : {0.3f, 0.7f, 1.0f}) {
        const double albedo = sampledAlbedo(brdf, viewAt(cosV), 200000, 3);
        EXPECT_LE(albedo, 1.0) << cosV;
        EXPECT_GE(albedo, 0.75) << cosV;
    }
}

TEST(GltfBrdf, IsReciprocal) {
    Pcg32 rng(11, 3);
    const GltfBrdf materials[] = {makeGltfBrdf(glm::vec3(0.9f, 0.5f, 0.2f), 1.0f, 0.3f),
            makeGltfBrdf(glm::vec3(0.2f, 0.7f, 0.4f), 0.0f, 0.8f),
            makeGltfBrdf(glm::vec3(0.6f), 0.5f, 0.1f)};
    for (const GltfBrdf& brdf : materials) {
        for (int i = 0; i < 1000; ++i) {
            glm::vec3 v = uniformSphere(rng.nextFloat(), rng.nextFloat());
            glm::vec3 l = uniformSphere(rng.nextFloat(), rng.nextFloat());
            v.z = std::abs(v.z);
            l.z = std::abs(l.z);
            const glm::vec3 forward = evaluateBrdf(brdf, kNormal, v, l);
            const glm::vec3 backward = evaluateBrdf(brdf, kNormal, l, v);
            for (int c = 0; c < 3; ++c) {
                EXPECT_NEAR(forward[c], backward[c], 1e-5f * std::max(1.0f, forward[c]));
            }
        }
    }
}

TEST(GltfBrdf, SamplingDensityIntegratesToOneOverTheSphere) {
    const GltfBrdf materials[] = {makeGltfBrdf(glm::vec3(1.0f), 1.0f, 0.5f),
            makeGltfBrdf(glm::vec3(0.5f), 0.0f, 0.4f), makeGltfBrdf(glm::vec3(0.7f), 1.0f, 0.9f)};
    for (const GltfBrdf& brdf : materials) {
        for (float cosV : {0.3f, 0.8f}) {
            Pcg32 rng(5, 4);
            const int n = 400000;
            double sum = 0.0;
            for (int i = 0; i < n; ++i) {
                const glm::vec3 l = uniformSphere(rng.nextFloat(), rng.nextFloat());
                sum += brdfPdf(brdf, kNormal, viewAt(cosV), l);
            }
            EXPECT_NEAR(sum / n * 4.0 * glm::pi<double>(), 1.0, 0.02) << cosV;
        }
    }
}

// Sampling draws directions with the density brdfPdf() reports: otherwise f cos / pdf would
// not average to the albedo that uniform sampling finds.
TEST(GltfBrdf, ImportanceSamplingAgreesWithUniformSampling) {
    const GltfBrdf materials[] = {makeGltfBrdf(glm::vec3(0.9f), 1.0f, 0.6f),
            makeGltfBrdf(glm::vec3(0.5f), 0.0f, 0.5f), makeGltfBrdf(glm::vec3(0.8f), 0.5f, 0.7f)};
    for (const GltfBrdf& brdf : materials) {
        for (float cosV : {0.4f, 0.95f}) {
            const double sampled = sampledAlbedo(brdf, viewAt(cosV), 200000, 9);
            const double uniform = uniformAlbedo(brdf, viewAt(cosV), 400000, 9);
            EXPECT_NEAR(sampled, uniform, 0.015 * uniform) << cosV;
        }
    }
}

} // namespace
} // namespace gi::reference
