#include "gi/vpl/VplSampler.h"

namespace gi::vpl {
namespace {

double weight(const RsmTexel& texel) {
    return double(texel.flux.r) + double(texel.flux.g) + double(texel.flux.b);
}

} // namespace

std::vector<shader::GpuVpl> drawVpls(const std::vector<RsmTexel>& texels, int count) {
    return drawVpls(texels, std::vector<float>(texels.size(), 1.0f), count);
}

std::vector<shader::GpuVpl> drawVpls(const std::vector<RsmTexel>& texels,
        const std::vector<float>& importance, int count) {
    std::vector<shader::GpuVpl> vpls;
    const auto drawWeight = [&](std::size_t i) {
        return i < importance.size() ? weight(texels[i]) * double(importance[i]) : 0.0;
    };
    double total = 0.0;
    for (std::size_t i = 0; i < texels.size(); ++i) total += drawWeight(i);
    if (count <= 0 || !(total > 0.0)) return vpls;
    vpls.reserve(std::size_t(count));
    const double step = total / double(count);
    double next = 0.5 * step;   // the middle of each stratum: the same VPLs every time
    double cumulative = 0.0;
    for (std::size_t i = 0; i < texels.size(); ++i) {
        const RsmTexel& texel = texels[i];
        const double w = drawWeight(i);
        if (w <= 0.0) continue;
        cumulative += w;
        const glm::vec3 flux = texel.flux * float(step / w);
        const float area = texel.area * float(step / w);   // the surface one copy stands for
        while (next < cumulative && int(vpls.size()) < count) {
            vpls.push_back({glm::vec4(texel.position, 1.0f), glm::vec4(texel.normal, 0.0f),
                    glm::vec4(flux, area)});
            next += step;
        }
    }
    return vpls;
}

} // namespace gi::vpl
