// Drawing VPLs from reflective-shadow-map texels: the count asked for, flux conserved per
// channel's sum, texels drawn in proportion to their flux, nothing from unlit texels.
#include "gi/vpl/VplSampler.h"

#include <gtest/gtest.h>

namespace gi::vpl {
namespace {

RsmTexel texel(float x, glm::vec3 flux) {
    return {glm::vec3(x, 0.0f, 0.0f), glm::vec3(0.0f, 1.0f, 0.0f), flux};
}

glm::dvec3 totalFlux(const std::vector<shader::GpuVpl>& vpls) {
    glm::dvec3 sum(0.0);
    for (const shader::GpuVpl& v : vpls) sum += glm::dvec3(glm::vec3(v.flux));
    return sum;
}

TEST(VplSampler, DrawsTheCountAndKeepsTheFlux) {
    std::vector<RsmTexel> texels;
    for (int i = 0; i < 1000; ++i) {
        texels.push_back(texel(float(i), glm::vec3(0.01f * float(i % 7), 0.02f, 0.003f)));
    }
    glm::dvec3 expected(0.0);
    for (const RsmTexel& t : texels) expected += glm::dvec3(t.flux);
    const std::vector<shader::GpuVpl> vpls = drawVpls(texels, 256);
    ASSERT_EQ(vpls.size(), 256u);
    const glm::dvec3 got = totalFlux(vpls);
    // Colour is carried per texel, so each channel's total is only kept in expectation; the
    // channels' sum is kept exactly.
    EXPECT_NEAR(got.r + got.g + got.b, expected.r + expected.g + expected.b,
            1e-4 * (expected.r + expected.g + expected.b));
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], expected[c], 0.05 * expected[c]) << c;
}

TEST(VplSampler, DrawsInProportionToFluxAndSkipsUnlitTexels) {
    const std::vector<RsmTexel> texels = {texel(0.0f, glm::vec3(3.0f)), texel(1.0f, glm::vec3(0.0f)),
            texel(2.0f, glm::vec3(1.0f))};
    const std::vector<shader::GpuVpl> vpls = drawVpls(texels, 100);
    ASSERT_EQ(vpls.size(), 100u);
    int first = 0, unlit = 0;
    for (const shader::GpuVpl& v : vpls) {
        first += v.position.x == 0.0f;
        unlit += v.position.x == 1.0f;
        EXPECT_FLOAT_EQ(v.flux.r, 0.04f);   // every VPL carries a hundredth of the 12 W
    }
    EXPECT_EQ(first, 75);
    EXPECT_EQ(unlit, 0);
    EXPECT_TRUE(drawVpls({texel(0.0f, glm::vec3(0.0f))}, 10).empty());
}

TEST(VplSampler, EveryVplCarriesTheSurfaceItStandsFor) {
    std::vector<RsmTexel> texels = {texel(0.0f, glm::vec3(3.0f)), texel(1.0f, glm::vec3(1.0f))};
    texels[0].area = 0.3f;
    texels[1].area = 0.5f;
    const std::vector<shader::GpuVpl> vpls = drawVpls(texels, 100);
    double area = 0.0;
    for (const shader::GpuVpl& v : vpls) {
        // 75 copies share the first texel's 0.3 m^2, 25 the second's 0.5 m^2.
        EXPECT_FLOAT_EQ(v.flux.w, v.position.x == 0.0f ? 0.004f : 0.02f);
        area += double(v.flux.w);
    }
    EXPECT_NEAR(area, 0.8, 1e-5);
}

} // namespace
} // namespace gi::vpl
