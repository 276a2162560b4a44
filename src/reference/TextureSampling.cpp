#include "reference/TextureSampling.h"

#include "core/Colour.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

namespace gi::reference {
namespace {

enum GlWrap : int { kRepeat = 10497, kClampToEdge = 33071, kMirroredRepeat = 33648 };

const std::array<float, 256>& srgbTable() {
    static const std::array<float, 256> table = [] {
        std::array<float, 256> t{};
        for (int i = 0; i < 256; ++i) t[std::size_t(i)] = core::srgbToLinear(float(i) / 255.0f);
        return t;
    }();
    return table;
}

// Folds a texture coordinate into [0, 1] by the sampler's wrap mode (for REPEAT, [0, 1)).
float wrapCoordinate(float u, int wrap) {
    if (!std::isfinite(u)) return 0.0f;
    if (wrap == kClampToEdge) return std::clamp(u, 0.0f, 1.0f);
    if (wrap == kMirroredRepeat) {
        const float m = u - 2.0f * std::floor(0.5f * u);
        return m > 1.0f ? 2.0f - m : m;
    }
    return u - std::floor(u);
}

int wrapIndex(int i, int size, int wrap) {
    if (wrap == kRepeat) return i < 0 ? i + size : (i >= size ? i - size : i);
    return std::clamp(i, 0, size - 1);   // clamp; mirrored repeat reflects onto the edge texel
}

} // namespace

glm::vec4 sampleTexture(const scene::Texture& texture, glm::vec2 uv) {
    if (texture.width <= 0 || texture.height <= 0 ||
            texture.rgba8.size() < std::size_t(texture.width) * std::size_t(texture.height) * 4) {
        return glm::vec4(1.0f);
    }
    const float x = wrapCoordinate(uv.x, texture.wrapS) * float(texture.width) - 0.5f;
    const float y = wrapCoordinate(uv.y, texture.wrapT) * float(texture.height) - 0.5f;
    const float fx = std::floor(x), fy = std::floor(y);
    const float tx = x - fx, ty = y - fy;
    const int x0 = int(fx), y0 = int(fy);
    const int xs[2] = {wrapIndex(x0, texture.width, texture.wrapS),
            wrapIndex(x0 + 1, texture.width, texture.wrapS)};
    const int ys[2] = {wrapIndex(y0, texture.height, texture.wrapT),
            wrapIndex(y0 + 1, texture.height, texture.wrapT)};
    const float wx[2] = {1.0f - tx, tx};
    const float wy[2] = {1.0f - ty, ty};
    const std::array<float, 256>& table = srgbTable();
    glm::vec4 result(0.0f);
    for (int j = 0; j < 2; ++j) {
        for (int i = 0; i < 2; ++i) {
            const std::uint8_t* texel = texture.rgba8.data() +
                    (std::size_t(ys[j]) * std::size_t(texture.width) + std::size_t(xs[i])) * 4;
            glm::vec4 value;
            if (texture.srgb) {
                value = {table[texel[0]], table[texel[1]], table[texel[2]], 0.0f};
            } else {
                value = {float(texel[0]) / 255.0f, float(texel[1]) / 255.0f,
                        float(texel[2]) / 255.0f, 0.0f};
            }
            value.a = float(texel[3]) / 255.0f;
            result += (wx[i] * wy[j]) * value;
        }
    }
    return result;
}

} // namespace gi::reference
