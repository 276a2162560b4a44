#include "reference/AreaLightSampling.h"

#include "reference/SamplingMath.h"
#include "scene/EmissionLights.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace gi::reference {

AreaLightSampler::AreaLightSampler(const EmbreeState& state,
        const std::vector<scene::Light>& lights)
    : mState(state) {
    std::vector<double> power;
    for (const scene::Light& light : lights) {
        if (light.type != scene::LightType::Area) continue;
        for (const scene::EmitterTriangle& source : light.emitters) {
            Emitter e;
            glm::vec3 p[3] = {source.p0, source.p1, source.p2};
            e.twoSided = source.twoSided;
            e.radiance = source.radiance;
            if (source.instance >= 0) {
                // Scene geometry: the Embree triangle is the authority on where it is and how
                // it emits; a stale or out-of-range reference is left to hits alone.
                if (std::size_t(source.instance) >= state.instanceTriangles.size()) continue;
                const TriangleRange range = state.instanceTriangles[std::size_t(source.instance)];
                if (source.triangle < 0 || std::uint32_t(source.triangle) >= range.count) continue;
                e.triangle = range.first + std::uint32_t(source.triangle);
                const glm::uvec3 t = state.triangles[e.triangle];
                p[0] = state.positions[t.x];
                p[1] = state.positions[t.y];
                p[2] = state.positions[t.z];
                e.twoSided = state.materials[state.triangleInfo[e.triangle].material].doubleSided;
                e.offset = state.triangleInfo[e.triangle].offset;
            } else {
                e.offset = std::max(kRelativeOffset * std::max({maxAbs(p[0]), maxAbs(p[1]),
                                                                maxAbs(p[2])}),
                        std::numeric_limits<float>::min());
            }
            e.p0 = p[0];
            e.edge1 = p[1] - p[0];
            e.edge2 = p[2] - p[0];
            const glm::vec3 n = glm::cross(e.edge1, e.edge2);
            e.area = 0.5f * glm::length(n);
            if (!(e.area > 0.0f) || !std::isfinite(e.area) || !isFinite(p[0]) ||
                    !isFinite(source.radiance) || std::min({source.radiance.x, source.radiance.y,
                                                    source.radiance.z}) < 0.0f) {
                continue;
            }
            e.normal = n / (2.0f * e.area);
            scene::EmitterTriangle weighed = source;
            weighed.twoSided = e.twoSided;
            const double w = scene::emitterPower(weighed);
            if (!(w > 0.0) || !std::isfinite(w)) continue;
            mEmitters.push_back(e);
            power.push_back(w);
        }
    }
    double total = 0.0;
    for (double w : power) total += w;
    if (mEmitters.empty() || !(total > 0.0) || !std::isfinite(total)) {
        mEmitters.clear();
        return;
    }
    double running = 0.0;
    for (std::size_t i = 0; i < mEmitters.size(); ++i) {
        running += power[i];
        mCumulative.push_back(float(running / total));
        mEmitters[i].pdfArea = float(power[i] / total) / mEmitters[i].area;
        if (mEmitters[i].triangle == kNoTriangle) continue;
        if (mTrianglePdf.empty()) mTrianglePdf.assign(state.triangles.size(), 0.0f);
        mTrianglePdf[mEmitters[i].triangle] += mEmitters[i].pdfArea;
    }
    mCumulative.back() = 1.0f;
}

bool AreaLightSampler::sample(float u1, float u2, EmitterSample& out) const {
    if (mEmitters.empty()) return false;
    const auto it = std::upper_bound(mCumulative.begin(), mCumulative.end(), u1);
    const std::size_t i =
            std::min(std::size_t(it - mCumulative.begin()), mEmitters.size() - 1);
    const float low = i == 0 ? 0.0f : mCumulative[i - 1];
    const float width = mCumulative[i] - low;
    const float reused = std::clamp(width > 0.0f ? (u1 - low) / width : 0.5f, 0.0f,
            1.0f - std::numeric_limits<float>::epsilon());
    // Uniform point on the triangle (PBRT 3rd ed. 13.6.5): barycentrics of corners 1 and 2.
    const float root = std::sqrt(reused);
    const float b1 = u2 * root;
    const float b2 = (1.0f - u2) * root;
    const Emitter& e = mEmitters[i];
    out.position = e.p0 + b1 * e.edge1 + b2 * e.edge2;
    out.normal = e.normal;
    out.twoSided = e.twoSided;
    out.offset = e.offset;
    out.onGeometry = e.triangle != kNoTriangle;
    out.pdfArea = out.onGeometry ? mTrianglePdf[e.triangle] : e.pdfArea;
    out.radiance = out.onGeometry ? mState.emission(e.triangle, b1, b2) : e.radiance;
    return maxComponent(out.radiance) > 0.0f;
}

} // namespace gi::reference
