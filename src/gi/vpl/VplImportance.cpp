#include "gi/vpl/VplImportance.h"

#include <algorithm>

namespace gi::vpl {
namespace {

double fluxWeight(const RsmTexel& texel) {
    return double(texel.flux.r) + double(texel.flux.g) + double(texel.flux.b);
}

// The samples as separate arrays, read in order by a loop over them without a branch (the
// compiler may vectorize it).
struct SampleArrays {
    std::vector<float> px, py, pz, nx, ny, nz;
    explicit SampleArrays(const std::vector<ViewSample>& samples) {
        for (const ViewSample& s : samples) {
            px.push_back(s.position.x);
            py.push_back(s.position.y);
            pz.push_back(s.position.z);
            nx.push_back(s.normal.x);
            ny.push_back(s.normal.y);
            nz.push_back(s.normal.z);
        }
    }
};

// Sum over the samples of cos at the texel x cos at the sample / max(B, r^2). The two cosines'
// product is (n_t . d)(-n_s . d) / r^2 for the unnormalized d, so no square root is taken.
float transferToSamples(const RsmTexel& texel, const SampleArrays& s, float clampArea) {
    float sum = 0.0f;
    const std::size_t count = s.px.size();
    for (std::size_t i = 0; i < count; ++i) {
        const float dx = s.px[i] - texel.position.x;
        const float dy = s.py[i] - texel.position.y;
        const float dz = s.pz[i] - texel.position.z;
        const float distance2 = std::max(dx * dx + dy * dy + dz * dz, 1e-12f);
        const float leaving = texel.normal.x * dx + texel.normal.y * dy + texel.normal.z * dz;
        const float arriving = -(s.nx[i] * dx + s.ny[i] * dy + s.nz[i] * dz);
        sum += std::max(leaving, 0.0f) * std::max(arriving, 0.0f) /
               (distance2 * std::max(clampArea, distance2));
    }
    return sum;
}

} // namespace

std::vector<float> viewImportance(const std::vector<RsmTexel>& texels,
        const std::vector<ViewSample>& samples, float clampArea) {
    std::vector<float> importance(texels.size(), 1.0f);
    if (samples.empty() || texels.empty()) return importance;
    const SampleArrays arrays(samples);
    double weighted = 0.0, flux = 0.0;
    for (std::size_t i = 0; i < texels.size(); ++i) {
        const float sum = transferToSamples(texels[i], arrays, clampArea);
        importance[i] = sum;
        weighted += fluxWeight(texels[i]) * double(sum);
        flux += fluxWeight(texels[i]);
    }
    const double mean = flux > 0.0 ? weighted / flux : 0.0;
    if (!(mean > 0.0)) {   // the view receives none of the light: no texel is preferred
        std::fill(importance.begin(), importance.end(), 1.0f);
        return importance;
    }
    for (float& value : importance) value += float(kViewIndependentShare * mean);
    return importance;
}

} // namespace gi::vpl
