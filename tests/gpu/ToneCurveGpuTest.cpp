// The viewer's tone curve (shaders/common/tonemap.glsl) against the one `render` applies
// (core/ToneMap.cpp): both read their constants from shaders/common/shared.h, and this holds
// the two formulas to the same values.
#include "ComputeProbe.h"
#include "GpuTest.h"

#include "core/ToneMap.h"

#include <vector>

namespace gi::test {
namespace {

class ToneCurveGpuTest : public GpuTest {};

TEST_F(ToneCurveGpuTest, GlslFilmicCurveMatchesTheCpuCurve) {
    std::vector<glm::vec4> inputs;
    for (float x : {0.0f, 0.01f, 0.18f, 0.5f, 1.0f, 2.0f, 5.0f, 20.0f, 1000.0f}) {
        inputs.emplace_back(x, x * 0.5f, x * 2.0f, 0.0f);
    }
    std::string error;
    const std::vector<glm::vec4> results =
            runComputeProbe<glm::vec4>("tests/gpu/shaders/tone_curve_probe.comp", inputs, error);
    ASSERT_EQ(results.size(), inputs.size()) << error;
    for (std::size_t i = 0; i < inputs.size(); ++i) {
        const glm::vec3 cpu = core::toneCurve(glm::vec3(inputs[i]), core::ToneCurve::Filmic);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(results[i][c], cpu[c], 1e-5f) << inputs[i][c];
    }
}

} // namespace
} // namespace gi::test
