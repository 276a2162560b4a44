// atlas.filter: the dilation pass averages each written texel's E_ind with the written texels
// of its 3x3 block that lie on its own surface (shaders/atlas/dilate.frag). The gather is
// deterministic without voxel visibility, so two renderers that differ only in the filter
// gather the same sums, and the filtered layer can be recomputed from the unfiltered one.
#include "AtlasGpuTestSupport.h"

#include <cmath>
#include <cstdio>

namespace gi::test {
namespace {

constexpr int kResolution = 256;
constexpr int kSamples = 16;

struct AtlasLayers {
    std::vector<glm::vec4> lit, position, normal;
};

AtlasLayers renderLayers(const scene::Scene& scene, bool filter) {
    Settings settings = atlasSettings(kResolution, kSamples);
    settings.atlas.filter = filter;
    AtlasFrame frame(scene, settings);
    frame.render({16, 16});
    const auto& textures = frame.gi().textures();
    return {frame.lit(), readAtlas(textures.position, textures.resolution),
            readAtlas(textures.normal, textures.resolution)};
}

// Texels the gather wrote: the unfiltered lit layer's alpha is 1 there (0.5 where the dilation
// filled a gutter texel, 0 elsewhere).
bool written(const AtlasLayers& layers, std::size_t i) { return layers.lit[i].a == 1.0f; }

// The filter's weight of neighbour q for texel p, written independently of the shader from its
// definition: same facing (cos >= 0.95), within a fifth of a texel edge of p's plane, within
// two edges of p, the edge the square root of the larger of the two texels' areas; tent
// weights 4 / 2 / 1 by Manhattan distance in the atlas, 4 for p itself whatever its area.
double surfaceWeight(const AtlasLayers& layers, std::size_t p, std::size_t q, glm::ivec2 offset) {
    if (q == p) return 4.0;
    if (!written(layers, q) || !(layers.position[q].w > 0.0f)) return 0.0;
    const glm::dvec3 n(layers.normal[p]);
    const glm::dvec3 d = glm::dvec3(layers.position[q]) - glm::dvec3(layers.position[p]);
    const double edge = std::sqrt(double(std::max(layers.position[p].w, layers.position[q].w)));
    const bool onSurface = glm::dot(glm::dvec3(layers.normal[q]), n) >= 0.95 &&
            std::abs(glm::dot(d, n)) <= 0.2 * edge && glm::dot(d, d) <= 4.0 * edge * edge;
    return onSurface ? double(4 >> (std::abs(offset.x) + std::abs(offset.y))) : 0.0;
}

// Mean squared difference between horizontally adjacent written texels of one surface.
double neighbourVariation(const AtlasLayers& layers) {
    double sum = 0.0;
    int count = 0;
    for (int y = 0; y < kResolution; ++y) {
        for (int x = 0; x + 1 < kResolution; ++x) {
            const std::size_t p = std::size_t(y * kResolution + x);
            if (!written(layers, p) || surfaceWeight(layers, p, p + 1, {1, 0}) <= 0.0) continue;
            const glm::dvec3 d = glm::dvec3(layers.lit[p + 1]) - glm::dvec3(layers.lit[p]);
            sum += glm::dot(d, d);
            ++count;
        }
    }
    EXPECT_GT(count, 10000);
    return sum / double(std::max(count, 1));
}

// Every filtered texel of the Cornell box equals the tent-weighted mean of the unfiltered
// texels on its own surface, within the half-float layers' rounding. A filter that mixed
// surfaces (a wall's texel with the floor's next to it at their edge, or texels of two charts
// side by side in the atlas) or weighted them otherwise fails here.
TEST_F(AtlasGpuTest, FilterAveragesEachTexelOverItsOwnSurface) {
    const scene::Scene scene = loadCornellBox();
    const AtlasLayers raw = renderLayers(scene, false);
    const AtlasLayers filtered = renderLayers(scene, true);
    int checked = 0, mixedSurfaces = 0, wrong = 0;
    for (int y = 0; y < kResolution; ++y) {
        for (int x = 0; x < kResolution; ++x) {
            const std::size_t p = std::size_t(y * kResolution + x);
            if (!written(raw, p)) continue;
            glm::dvec3 sum(0.0);
            double total = 0.0;
            bool otherSurfaceBeside = false;
            for (int dy = -1; dy <= 1; ++dy) {
                for (int dx = -1; dx <= 1; ++dx) {
                    const int qx = x + dx, qy = y + dy;
                    if (qx < 0 || qy < 0 || qx >= kResolution || qy >= kResolution) continue;
                    const std::size_t q = std::size_t(qy * kResolution + qx);
                    const double w = surfaceWeight(raw, p, q, {dx, dy});
                    otherSurfaceBeside |= written(raw, q) && w == 0.0;
                    sum += w * glm::dvec3(raw.lit[q]);
                    total += w;
                }
            }
            const glm::dvec3 expected = sum / total;
            const glm::dvec3 got(filtered.lit[p]);
            ++checked;
            mixedSurfaces += otherSurfaceBeside ? 1 : 0;
            for (int c = 0; c < 3; ++c) {
                if (std::abs(got[c] - expected[c]) > 2e-3 * expected[c] + 1e-6) ++wrong;
            }
        }
    }
    std::printf("%d texels checked, %d of them beside another surface's texels, %d channels "
                "off\n", checked, mixedSurfaces, wrong);
    EXPECT_GT(checked, 20000);
    EXPECT_GT(mixedSurfaces, 100) << "no texel had another surface beside it: nothing tested";
    EXPECT_EQ(wrong, 0);
}

// The noise the filter is for: 16 samples per texel leave the Cornell box's texels grainy,
// and the filtered neighbours differ far less (a 3x3 tent over independent estimates keeps
// 14% of their variance) while the light over all texels stays where it was.
TEST_F(AtlasGpuTest, FilterCutsTexelNoiseAndKeepsTheLight) {
    const scene::Scene scene = loadCornellBox();
    const AtlasLayers raw = renderLayers(scene, false);
    const AtlasLayers filtered = renderLayers(scene, true);
    const double before = neighbourVariation(raw), after = neighbourVariation(filtered);
    glm::dvec3 rawSum(0.0), filteredSum(0.0);
    for (std::size_t i = 0; i < raw.lit.size(); ++i) {
        if (!written(raw, i)) continue;
        rawSum += glm::dvec3(raw.lit[i]);
        filteredSum += glm::dvec3(filtered.lit[i]);
    }
    std::printf("adjacent texels' mean squared difference: %.6g unfiltered, %.6g filtered; "
                "summed E_ind (red) %.4g, %.4g\n", before, after, rawSum.r, filteredSum.r);
    EXPECT_LT(after, 0.3 * before);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(filteredSum[c], rawSum[c], 0.02 * rawSum[c]);
}

} // namespace
} // namespace gi::test
