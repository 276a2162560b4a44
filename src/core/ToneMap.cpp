#include "core/ToneMap.h"

#include "gl/Shared.h"

#include <algorithm>
#include <cmath>

namespace gi::core {

float luminance(const glm::vec3& rgb) {
    return 0.2126f * rgb.r + 0.7152f * rgb.g + 0.0722f * rgb.b;
}

float filmicCurve(float x) {
    x = std::max(x, 0.0f);
    const float a = float(TONE_ACES_A), b = float(TONE_ACES_B), c = float(TONE_ACES_C);
    const float d = float(TONE_ACES_D), e = float(TONE_ACES_E);
    return std::clamp(x * (a * x + b) / (x * (c * x + d) + e), 0.0f, 1.0f);
}

glm::vec3 toneCurve(const glm::vec3& exposed, ToneCurve curve) {
    if (curve == ToneCurve::Filmic) {
        return {filmicCurve(exposed.r), filmicCurve(exposed.g), filmicCurve(exposed.b)};
    }
    return glm::clamp(exposed, 0.0f, 1.0f);
}

std::optional<float> logAverageLuminance(const Image& image, const std::vector<float>& coverage) {
    double sum = 0.0;
    std::size_t count = 0;
    const std::size_t pixels = std::size_t(image.width) * std::size_t(image.height);
    for (std::size_t i = 0; i < pixels; ++i) {
        if (!coverage.empty() && !(coverage[i] > 0.5f)) continue;
        const float y = luminance({image.rgb[i * 3], image.rgb[i * 3 + 1], image.rgb[i * 3 + 2]});
        if (!(y > kMinLuminance)) continue;
        sum += std::log(double(y));
        ++count;
    }
    if (count == 0) return std::nullopt;
    return float(std::exp(sum / double(count)));
}

float autoExposure(float logAverage) {
    const float limit = std::exp2(kMaxExposureEv);
    return std::clamp(kAutoExposureKey / logAverage, 1.0f / limit, limit);
}

float exposureFor(const ToneMapping& mapping, const Image& image,
        const std::vector<float>& coverage) {
    if (!mapping.autoExposure) return std::exp2(mapping.ev);
    const std::optional<float> average = logAverageLuminance(image, coverage);
    return average ? autoExposure(*average) : 1.0f;
}

Image applyToneMapping(const Image& image, float exposure, ToneCurve curve) {
    Image mapped = image;
    for (std::size_t i = 0; i + 2 < mapped.rgb.size(); i += 3) {
        const glm::vec3 exposed =
                glm::vec3(mapped.rgb[i], mapped.rgb[i + 1], mapped.rgb[i + 2]) * exposure;
        const glm::vec3 out = toneCurve(exposed, curve);
        mapped.rgb[i] = out.r;
        mapped.rgb[i + 1] = out.g;
        mapped.rgb[i + 2] = out.b;
    }
    return mapped;
}

std::optional<ToneCurve> parseToneCurve(const std::string& name) {
    if (name == "none") return ToneCurve::None;
    if (name == "filmic") return ToneCurve::Filmic;
    return std::nullopt;
}

const char* toneCurveName(ToneCurve curve) {
    return curve == ToneCurve::Filmic ? "filmic" : "none";
}

} // namespace gi::core
