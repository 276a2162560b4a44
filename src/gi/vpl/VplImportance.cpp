#include "gi/vpl/VplImportance.h"

#include <algorithm>

namespace gi::vpl {
namespace {

double fluxWeight(const RsmTexel& texel) {
    return double(texel.flux.r) + double(texel.flux.g) + double(texel.flux.b);
}

float transfer(const RsmTexel& texel, const ViewSample& sample, float clampArea) {
    const glm::vec3 toSample = sample.position - texel.position;
    const float distance2 = glm::dot(toSample, toSample);
    if (!(distance2 > 0.0f)) return 0.0f;
    const glm::vec3 direction = toSample * (1.0f / std::sqrt(distance2));
    const float leaving = glm::dot(texel.normal, direction);
    const float arriving = -glm::dot(sample.normal, direction);
    if (leaving <= 0.0f || arriving <= 0.0f) return 0.0f;
    return leaving * arriving / std::max(clampArea, distance2);
}

} // namespace

std::vector<float> viewImportance(const std::vector<RsmTexel>& texels,
        const std::vector<ViewSample>& samples, float clampArea) {
    std::vector<float> importance(texels.size(), 1.0f);
    if (samples.empty() || texels.empty()) return importance;
    double weighted = 0.0, flux = 0.0;
    for (std::size_t i = 0; i < texels.size(); ++i) {
        float sum = 0.0f;
        for (const ViewSample& sample : samples) sum += transfer(texels[i], sample, clampArea);
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
