// The view's importance for drawing VPLs: texels whose light the view's surfaces can receive
// get more VPLs, texels facing away keep the view-independent share, and every texel's
// expected flux is still its own.
#include "gi/vpl/VplImportance.h"
#include "gi/vpl/VplSampler.h"

#include <gtest/gtest.h>

namespace gi::vpl {
namespace {

RsmTexel upward(float x, float flux) {
    return {glm::vec3(x, 0.0f, 0.0f), glm::vec3(0.0f, 1.0f, 0.0f), glm::vec3(flux)};
}

// A floor from x = 0 to 10 and the view's surface: a ceiling patch above x = 1 facing down.
std::vector<RsmTexel> floorTexels() {
    std::vector<RsmTexel> texels;
    for (int i = 0; i < 100; ++i) texels.push_back(upward(0.1f * float(i) + 0.05f, 1.0f));
    return texels;
}

const std::vector<ViewSample> kCeilingAboveX1 = {
        {glm::vec3(1.0f, 1.0f, 0.0f), glm::vec3(0.0f, -1.0f, 0.0f)}};

TEST(VplImportance, TexelsTheViewCanReceiveWeighMore) {
    const std::vector<RsmTexel> texels = floorTexels();
    const std::vector<float> importance = viewImportance(texels, kCeilingAboveX1, 0.01f);
    ASSERT_EQ(importance.size(), texels.size());
    // Straight under the patch (x = 1.05) against 8 m away (x = 9.05): cos^4 / r^2 falls
    // about 4000-fold; the far texel keeps the view-independent share.
    EXPECT_GT(importance[10], 5.0f * importance[90]);
    EXPECT_GT(importance[90], 0.0f);
}

TEST(VplImportance, TexelsFacingAwayKeepOnlyTheViewIndependentShare) {
    std::vector<RsmTexel> texels = floorTexels();
    texels[10].normal = glm::vec3(0.0f, -1.0f, 0.0f);   // faces away from the ceiling
    const std::vector<float> importance = viewImportance(texels, kCeilingAboveX1, 0.01f);
    EXPECT_GT(importance[10], 0.0f);
    EXPECT_LT(importance[10], importance[11] / 5.0f);
}

TEST(VplImportance, NoViewSamplesWeighEveryTexelAlike) {
    const std::vector<float> importance = viewImportance(floorTexels(), {}, 0.01f);
    for (float value : importance) EXPECT_EQ(value, 1.0f);
}

TEST(VplImportance, DrawnByImportanceEveryTexelKeepsItsFluxInExpectation) {
    const std::vector<RsmTexel> texels = floorTexels();
    const std::vector<float> importance = viewImportance(texels, kCeilingAboveX1, 0.01f);
    const std::vector<shader::GpuVpl> vpls = drawVpls(texels, importance, 1000);
    ASSERT_EQ(vpls.size(), 1000u);
    double total = 0.0, nearFlux = 0.0;
    int nearCount = 0;
    for (const shader::GpuVpl& v : vpls) {
        total += double(v.flux.r);
        if (v.position.x < 2.0f) {
            nearFlux += double(v.flux.r);
            ++nearCount;
        }
    }
    EXPECT_NEAR(total, 100.0, 0.05);   // float rounding of 1000 products
    // The 20 texels under and around the patch (20 W of the floor's 100) get most of the
    // VPLs, each carrying less, and still send their 20 W.
    EXPECT_GT(nearCount, 500);
    EXPECT_NEAR(nearFlux, 20.0, 0.5);
}

} // namespace
} // namespace gi::vpl
