// Next-event estimation of area lights: one pool of every area light's triangles, a triangle
// picked in proportion to its power (luminance of its radiance x area x sides) and a uniform
// point on it. The same density, looked up for a triangle a bounce ray hits, weighs that hit
// against the light sample (multiple importance sampling, PathTracer.h).
//
// Triangles from scene geometry (EmitterTriangle::instance >= 0) are taken from the Embree
// scene, so a sampled point and a ray hit see the same triangle and the same emission: the
// material's emissive factor x texture at that point, on the front side unless the material
// is double-sided. Command-line emitters (instance -1) have no geometry: their uniform
// radiance and twoSided flag apply, and only light sampling finds them.
#pragma once

#include "reference/EmbreeScene.h"
#include "scene/Scene.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace gi::reference {

struct EmitterSample {
    glm::vec3 position{0.0f};
    glm::vec3 normal{0.0f};       // unit, front side
    glm::vec3 radiance{0.0f};     // emitted on the sides that emit (twoSided)
    bool twoSided = false;
    bool onGeometry = false;      // a bounce ray can hit it (then the sample is MIS-weighted)
    float pdfArea = 0.0f;         // density of this point per m^2 of emitting surface
    float offset = 0.0f;          // metres a shadow ray stops in front of it
};

class AreaLightSampler {
public:
    AreaLightSampler(const EmbreeState& state, const std::vector<scene::Light>& lights);

    bool empty() const { return mEmitters.empty(); }

    // A point of the pool from two uniform numbers (u1 picks the triangle and is reused,
    // rescaled, for the point). False when the pool is empty or the point emits nothing.
    bool sample(float u1, float u2, EmitterSample& out) const;

    // The area density with which sample() picks points of Embree triangle `triangle`;
    // 0 when it belongs to no area light (its emission is then found by hits alone).
    float pdfArea(std::uint32_t triangle) const {
        return triangle < mTrianglePdf.size() ? mTrianglePdf[triangle] : 0.0f;
    }

private:
    static constexpr std::uint32_t kNoTriangle = 0xFFFFFFFFu;
    struct Emitter {
        glm::vec3 p0{0.0f}, edge1{0.0f}, edge2{0.0f}, normal{0.0f};
        glm::vec3 radiance{0.0f};            // command-line emitters only
        float area = 0.0f;
        float pdfArea = 0.0f;                // selection probability / area
        float offset = 0.0f;
        std::uint32_t triangle = kNoTriangle; // Embree triangle, or none
        bool twoSided = false;
    };

    const EmbreeState& mState;
    std::vector<Emitter> mEmitters;
    std::vector<float> mCumulative;          // selection CDF, last entry 1
    std::vector<float> mTrianglePdf;         // per Embree triangle (empty: none on geometry)
};

} // namespace gi::reference
