// The viewer's tone curve (shaders/common/tonemap.glsl) against the one `render` applies
// (core/ToneMap.cpp): both read their constants from shaders/common/shared.h, and this holds
// the two formulas to the same values.
#include "GpuTest.h"

#include "core/ToneMap.h"
#include "gl/Objects.h"
#include "gl/ShaderLibrary.h"

#include <glad/gl.h>

#include <filesystem>
#include <vector>

namespace gi::test {
namespace {

class ToneCurveGpuTest : public GpuTest {};

TEST_F(ToneCurveGpuTest, GlslFilmicCurveMatchesTheCpuCurve) {
    gl::ShaderLibrary library(std::filesystem::path(sourcePath("shaders")).parent_path());
    std::string error;
    const gl::ProgramRef program = library.build({"test/tone_curve_probe",
            {{GL_COMPUTE_SHADER, "tests/gpu/shaders/tone_curve_probe.comp"}}, {}}, error);
    ASSERT_TRUE(program) << error;
    std::vector<glm::vec4> inputs;
    for (float x : {0.0f, 0.01f, 0.18f, 0.5f, 1.0f, 2.0f, 5.0f, 20.0f, 1000.0f}) {
        inputs.emplace_back(x, x * 0.5f, x * 2.0f, 0.0f);
    }
    const gl::Buffer input = gl::createBuffer(inputs.size() * sizeof(glm::vec4), inputs.data(), 0,
            "test/tone-inputs");
    const gl::Buffer output = gl::createBuffer(inputs.size() * sizeof(glm::vec4), nullptr, 0,
            "test/tone-results");
    glUseProgram(program.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, input.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, output.id());
    glDispatchCompute(GLuint(inputs.size()), 1, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    std::vector<glm::vec4> results(inputs.size());
    glGetNamedBufferSubData(output.id(), 0, GLsizeiptr(results.size() * sizeof(glm::vec4)),
            results.data());
    for (std::size_t i = 0; i < inputs.size(); ++i) {
        const glm::vec3 cpu = core::toneCurve(glm::vec3(inputs[i]), core::ToneCurve::Filmic);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(results[i][c], cpu[c], 1e-5f) << inputs[i][c];
    }
}

} // namespace
} // namespace gi::test
