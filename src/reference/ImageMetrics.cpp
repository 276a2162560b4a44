#include "reference/ImageMetrics.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace gi::reference {

ImageErrors measureImageError(const core::Image& actual, const core::Image& reference,
        std::span<const float> mask, float threshold) {
    constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
    constexpr double kInf = std::numeric_limits<double>::infinity();
    ImageErrors errors;
    const std::size_t pixelCount = std::size_t(std::max(reference.width, 0)) *
                                   std::size_t(std::max(reference.height, 0));
    if (actual.width != reference.width || actual.height != reference.height ||
            actual.rgb.size() != pixelCount * 3 || reference.rgb.size() != pixelCount * 3 ||
            (!mask.empty() && mask.size() != pixelCount)) {
        errors.sizeMismatch = true;
        errors.relativeRmse = errors.energyRatio = errors.rmse = errors.maxAbs = kNaN;
        return errors;
    }
    double squaredError = 0.0, squaredReference = 0.0, sumActual = 0.0, sumReference = 0.0;
    double maxAbs = 0.0;
    for (std::size_t p = 0; p < pixelCount; ++p) {
        if (!mask.empty() && !(mask[p] > threshold)) continue;
        ++errors.pixels;
        for (std::size_t c = 0; c < 3; ++c) {
            const double a = actual.rgb[3 * p + c], b = reference.rgb[3 * p + c];
            const double difference = a - b;
            squaredError += difference * difference;
            squaredReference += b * b;
            sumActual += a;
            sumReference += b;
            const double absolute = std::abs(difference);
            maxAbs = std::isnan(absolute) || std::isnan(maxAbs) ? kNaN : std::max(maxAbs, absolute);
        }
    }
    if (errors.pixels == 0) {
        errors.relativeRmse = errors.energyRatio = errors.rmse = errors.maxAbs = kNaN;
        return errors;
    }
    errors.rmse = std::sqrt(squaredError / (3.0 * double(errors.pixels)));
    errors.maxAbs = maxAbs;
    if (squaredReference > 0.0 || std::isnan(squaredReference)) {
        errors.relativeRmse = std::sqrt(squaredError / squaredReference);
    } else {
        errors.relativeRmse = squaredError == 0.0 ? 0.0 : (std::isnan(squaredError) ? kNaN : kInf);
    }
    if (sumReference != 0.0 || std::isnan(sumReference)) {
        errors.energyRatio = sumActual / sumReference;
    } else {
        errors.energyRatio = sumActual == 0.0 ? 1.0 : (std::isnan(sumActual) ? kNaN : kInf);
    }
    return errors;
}

} // namespace gi::reference
