#include "gi/vpl/VplSampler.h"

namespace gi::vpl {
namespace {

double weight(const RsmTexel& texel) {
    return double(texel.flux.r) + double(texel.flux.g) + double(texel.flux.b);
}

} // namespace

std::vector<shader::GpuVpl> drawVpls(const std::vector<RsmTexel>& texels, int count) {
    std::vector<shader::GpuVpl> vpls;
    double total = 0.0;
    for (const RsmTexel& texel : texels) total += weight(texel);
    if (count <= 0 || !(total > 0.0)) return vpls;
    vpls.reserve(std::size_t(count));
    const double step = total / double(count);
    double next = 0.5 * step;   // the middle of each stratum: the same VPLs every time
    double cumulative = 0.0;
    for (const RsmTexel& texel : texels) {
        const double w = weight(texel);
        if (w <= 0.0) continue;
        cumulative += w;
        const glm::vec3 flux = texel.flux * float(step / w);
        while (next < cumulative && int(vpls.size()) < count) {
            vpls.push_back({glm::vec4(texel.position, 1.0f), glm::vec4(texel.normal, 0.0f),
                    glm::vec4(flux, 0.0f)});
            next += step;
        }
    }
    return vpls;
}

} // namespace gi::vpl
