#include "core/Image.h"

#include <cmath>

namespace gi::core {

Image boxDownsample(const Image& image, int factor) {
    if (factor <= 1) return image;
    Image result(image.width / factor, image.height / factor);
    const float weight = 1.0f / float(factor * factor);
    for (int y = 0; y < result.height; ++y) {
        for (int x = 0; x < result.width; ++x) {
            glm::vec3 sum(0.0f);
            for (int dy = 0; dy < factor; ++dy) {
                for (int dx = 0; dx < factor; ++dx) sum += image.at(x * factor + dx, y * factor + dy);
            }
            result.set(x, y, sum * weight);
        }
    }
    return result;
}

bool allFinite(const Image& image) {
    for (float v : image.rgb) {
        if (!std::isfinite(v)) return false;
    }
    return true;
}

} // namespace gi::core
