// Runs a test's compute shader over an array of cases: one work group per case reads
// inputs[gl_WorkGroupID.x] from the storage buffer at binding 0 and writes one result to the
// buffer at binding 1 (literal bindings: probe shaders are test code, not the renderer's
// slots in shared.h). The shader path is relative to the source tree, so a probe includes
// the project's own GLSL from shaders/ as the renderer does. Needs a current GL context.
#pragma once

#include "GpuTest.h"

#include "gl/Objects.h"
#include "gl/ShaderLibrary.h"

#include <glad/gl.h>

#include <filesystem>
#include <string>
#include <vector>

namespace gi::test {

template <class Result, class Input>
[[nodiscard]] std::vector<Result> runComputeProbe(const std::string& shaderPath,
        const std::vector<Input>& inputs, std::string& error) {
    gl::ShaderLibrary library(std::filesystem::path(sourcePath("shaders")).parent_path());
    const gl::ProgramRef program =
            library.build({"test/" + std::filesystem::path(shaderPath).stem().string(),
                                  {{GL_COMPUTE_SHADER, shaderPath}}, {}},
                    error);
    if (!program) return {};
    const gl::Buffer input = gl::createBuffer(inputs.size() * sizeof(Input), inputs.data(), 0,
            "test/probe-inputs");
    const gl::Buffer output =
            gl::createBuffer(inputs.size() * sizeof(Result), nullptr, 0, "test/probe-results");
    glUseProgram(program.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, input.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, output.id());
    glDispatchCompute(GLuint(inputs.size()), 1, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    std::vector<Result> results(inputs.size());
    glGetNamedBufferSubData(output.id(), 0, GLsizeiptr(results.size() * sizeof(Result)),
            results.data());
    return results;
}

} // namespace gi::test
