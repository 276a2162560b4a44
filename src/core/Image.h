// A linear-radiance RGB image on the CPU: what a render produces before it is encoded, what
// image tests and metrics compare, and what the reference renderer writes.
#pragma once

#include <glm/glm.hpp>

#include <vector>

namespace gi::core {

struct Image {
    int width = 0, height = 0;
    std::vector<float> rgb;   // width * height * 3 floats, rows top to bottom, linear radiance

    Image() = default;
    Image(int w, int h) : width(w), height(h), rgb(std::size_t(w) * std::size_t(h) * 3, 0.0f) {}

    bool empty() const { return width <= 0 || height <= 0; }
    glm::vec3 at(int x, int y) const {
        const std::size_t i = (std::size_t(y) * std::size_t(width) + std::size_t(x)) * 3;
        return {rgb[i], rgb[i + 1], rgb[i + 2]};
    }
    void set(int x, int y, const glm::vec3& value) {
        const std::size_t i = (std::size_t(y) * std::size_t(width) + std::size_t(x)) * 3;
        rgb[i] = value.r;
        rgb[i + 1] = value.g;
        rgb[i + 2] = value.b;
    }
};

// Averages factor x factor blocks: a pixel's value is the mean radiance over its square.
[[nodiscard]] Image boxDownsample(const Image& image, int factor);

// True when every value is finite (no NaN, no Inf).
[[nodiscard]] bool allFinite(const Image& image);

} // namespace gi::core
