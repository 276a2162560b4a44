#include "gi/atlas/Hammersley.h"

#include <cmath>

namespace gi::atlas {

double radicalInverse2(std::uint32_t i) {
    // Reverse the 32 bits; the result read as a fraction is Phi_2(i).
    i = (i << 16) | (i >> 16);
    i = ((i & 0x00ff00ffu) << 8) | ((i & 0xff00ff00u) >> 8);
    i = ((i & 0x0f0f0f0fu) << 4) | ((i & 0xf0f0f0f0u) >> 4);
    i = ((i & 0x33333333u) << 2) | ((i & 0xccccccccu) >> 2);
    i = ((i & 0x55555555u) << 1) | ((i & 0xaaaaaaaau) >> 1);
    return double(i) * (1.0 / 4294967296.0);
}

std::vector<glm::vec2> hammersley(int count) {
    std::vector<glm::vec2> points;
    if (count <= 0) return points;
    points.reserve(std::size_t(count));
    for (int i = 0; i < count; ++i) {
        points.emplace_back(
                float(double(i) / double(count)), float(radicalInverse2(std::uint32_t(i))));
    }
    return points;
}

glm::vec2 cranleyPattersonOffset(std::uint32_t k) {
    constexpr double g = 1.32471795724474602596; // plastic number, x^3 = x + 1
    const double a = double(k) / g, b = double(k) / (g * g);
    return glm::vec2(float(a - std::floor(a)), float(b - std::floor(b)));
}

} // namespace gi::atlas
