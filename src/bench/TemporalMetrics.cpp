#include "bench/TemporalMetrics.h"

#include "core/ToneMap.h"

#include <cmath>

namespace gi::bench {
namespace {

constexpr float kCovered = 0.5f;

bool covered(const CoveredFrame& frame, std::size_t pixel) {
    return frame.coverage.empty() || frame.coverage[pixel] > kCovered;
}

double luminanceAt(const core::Image& image, std::size_t pixel) {
    const std::size_t i = pixel * 3;
    return double(core::luminance({image.rgb[i], image.rgb[i + 1], image.rgb[i + 2]}));
}

std::size_t pixelCount(const core::Image& image) {
    return std::size_t(image.width) * std::size_t(image.height);
}

bool sameShape(const CoveredFrame& a, const CoveredFrame& b) {
    return a.image.width == b.image.width && a.image.height == b.image.height;
}

} // namespace

double relativeFrameChange(const CoveredFrame& a, const CoveredFrame& b) {
    if (!sameShape(a, b)) return 0.0;
    double change = 0.0, level = 0.0;
    for (std::size_t p = 0; p < pixelCount(a.image); ++p) {
        if (!covered(a, p) || !covered(b, p)) continue;
        const double ya = luminanceAt(a.image, p), yb = luminanceAt(b.image, p);
        change += std::abs(yb - ya);
        level += 0.5 * (ya + yb);
    }
    return level > 0.0 ? change / level : 0.0;
}

double meanFrameChange(const std::vector<CoveredFrame>& frames) {
    if (frames.size() < 2) return 0.0;
    double sum = 0.0;
    for (std::size_t i = 1; i < frames.size(); ++i) {
        sum += relativeFrameChange(frames[i - 1], frames[i]);
    }
    return sum / double(frames.size() - 1);
}

double meanLuminanceOfRows(const CoveredFrame& frame, int firstRow) {
    double sum = 0.0;
    int count = 0;
    for (int y = std::max(firstRow, 0); y < frame.image.height; ++y) {
        for (int x = 0; x < frame.image.width; ++x) {
            const std::size_t p = std::size_t(y) * std::size_t(frame.image.width) + std::size_t(x);
            if (!covered(frame, p)) continue;
            sum += luminanceAt(frame.image, p);
            ++count;
        }
    }
    return count > 0 ? sum / count : 0.0;
}

std::vector<bool> changedPixels(const CoveredFrame& a, const CoveredFrame& b, double threshold) {
    std::vector<bool> changed(pixelCount(a.image), false);
    if (!sameShape(a, b)) return changed;
    for (std::size_t p = 0; p < changed.size(); ++p) {
        changed[p] = covered(a, p) && covered(b, p) &&
                     std::abs(luminanceAt(a.image, p) - luminanceAt(b.image, p)) > threshold;
    }
    return changed;
}

double trailBrightness(const CoveredFrame& history, const CoveredFrame& fresh,
        const std::vector<bool>& region, double floorLight) {
    if (!sameShape(history, fresh) || region.size() != pixelCount(fresh.image) ||
            floorLight <= 0.0) {
        return 0.0;
    }
    double sum = 0.0;
    int count = 0;
    for (std::size_t p = 0; p < region.size(); ++p) {
        if (!region[p] || !covered(fresh, p)) continue;
        sum += std::abs(luminanceAt(history.image, p) - luminanceAt(fresh.image, p));
        ++count;
    }
    return count > 0 ? sum / count / floorLight : 0.0;
}

CoveredFrame blockMean(const CoveredFrame& frame, int factor) {
    CoveredFrame result{core::boxDownsample(frame.image, factor), {}};
    if (frame.coverage.empty() || factor <= 1) {
        result.coverage = frame.coverage;
        return result;
    }
    core::Image coverage(frame.image.width, frame.image.height);
    for (std::size_t p = 0; p < frame.coverage.size(); ++p) {
        coverage.rgb[p * 3] = frame.coverage[p];
    }
    const core::Image averaged = core::boxDownsample(coverage, factor);
    result.coverage.resize(pixelCount(averaged));
    for (std::size_t p = 0; p < result.coverage.size(); ++p) {
        result.coverage[p] = averaged.rgb[p * 3];
    }
    return result;
}

core::Image differenceImage(const core::Image& a, const core::Image& b, float gain) {
    core::Image out(a.width, a.height);
    if (a.width != b.width || a.height != b.height) return out;
    for (std::size_t p = 0; p < pixelCount(a); ++p) {
        const float d = float(std::abs(luminanceAt(a, p) - luminanceAt(b, p))) * gain;
        for (int c = 0; c < 3; ++c) out.rgb[p * 3 + std::size_t(c)] = d;
    }
    return out;
}

} // namespace gi::bench
