#include "gi/vpl/VplGBufferPass.h"

#include "gl/RenderTarget.h"
#include "gl/Shared.h"

#include <algorithm>
#include <cstdio>

namespace gi::vpl {

bool VplGBufferPass::init(gl::ShaderLibrary& shaders, std::string& error) {
    mDepthProgram = shaders.build({"vpl/gbuffer_depth",
            {{GL_VERTEX_SHADER, "vpl/gbuffer.vert"},
             {GL_FRAGMENT_SHADER, "common/depth_only.frag"}},
            {}}, error);
    if (!mDepthProgram) return false;
    mProgram = shaders.build({"vpl/gbuffer",
            {{GL_VERTEX_SHADER, "vpl/gbuffer.vert"}, {GL_FRAGMENT_SHADER, "vpl/gbuffer.frag"}},
            {}}, error);
    return bool(mProgram);
}

bool VplGBufferPass::resize(glm::ivec2 size) {
    size = glm::max(size, glm::ivec2(1));
    if (size == mSize) return true;
    mPosition = gl::createTargetTexture({GL_RGBA32F, "vpl/gbuffer_position"}, size);
    mNormal = gl::createTargetTexture({GL_RGBA16F, "vpl/gbuffer_normal"}, size);
    mDepth = gl::createTargetTexture({GL_DEPTH_COMPONENT32F, "vpl/gbuffer_depth"}, size);
    std::string error;
    if (!gl::attachFramebuffer(mFramebuffer, "vpl/gbuffer", {&mPosition, &mNormal}, &mDepth,
                error)) {
        std::fprintf(stderr, "vpl: %s\n", error.c_str());
        mSize = glm::ivec2(0);
        return false;
    }
    mSize = size;
    return true;
}

void VplGBufferPass::execute(const scene::GpuScene& scene, const gl::Buffer& frameUniforms,
        glm::ivec2 size, gl::GpuProfiler& profiler) {
    if (!resize(size)) return;
    gl::GpuScope scope(profiler, "vpl/gbuffer");
    glBindFramebuffer(GL_FRAMEBUFFER, mFramebuffer.id());
    glViewport(0, 0, mSize.x, mSize.y);
    const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    const float far = 1.0f;
    glClearNamedFramebufferfv(mFramebuffer.id(), GL_COLOR, 0, zero);
    glClearNamedFramebufferfv(mFramebuffer.id(), GL_COLOR, 1, zero);
    glDepthMask(GL_TRUE);
    glClearNamedFramebufferfv(mFramebuffer.id(), GL_DEPTH, 0, &far);
    glEnable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    glBindBufferBase(GL_UNIFORM_BUFFER, BIND_UBO_FRAME, frameUniforms.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BIND_SSBO_MATERIALS, scene.materialBuffer().id());
    glDepthFunc(GL_LESS);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glUseProgram(mDepthProgram.id());
    scene.drawAll(mDepthProgram.id(), true);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDepthFunc(GL_LEQUAL);
    glDepthMask(GL_FALSE);
    glUseProgram(mProgram.id());
    scene.drawAll(mProgram.id(), true);
    glDepthMask(GL_TRUE);
    glDepthFunc(GL_LESS);
    glDisable(GL_DEPTH_TEST);
    glUseProgram(0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

std::vector<ViewSample> VplGBufferPass::readSamples(int perSide) const {
    std::vector<ViewSample> samples;
    if (mSize.x <= 0 || mSize.y <= 0 || perSide <= 0) return samples;
    // Only the rows that hold cell centres are read back.
    std::vector<glm::vec4> position(std::size_t(mSize.x)), normal(std::size_t(mSize.x));
    const GLsizei bytes = GLsizei(position.size() * sizeof(glm::vec4));
    samples.reserve(std::size_t(perSide) * std::size_t(perSide));
    for (int cy = 0; cy < perSide; ++cy) {
        const int y = std::min(mSize.y - 1, int((cy + 0.5f) * float(mSize.y) / float(perSide)));
        glGetTextureSubImage(mPosition.id(), 0, 0, y, 0, mSize.x, 1, 1, GL_RGBA, GL_FLOAT, bytes,
                position.data());
        glGetTextureSubImage(mNormal.id(), 0, 0, y, 0, mSize.x, 1, 1, GL_RGBA, GL_FLOAT, bytes,
                normal.data());
        for (int cx = 0; cx < perSide; ++cx) {
            const auto x = std::size_t(
                    std::min(mSize.x - 1, int((cx + 0.5f) * float(mSize.x) / float(perSide))));
            if (!(position[x].w > 0.0f)) continue;   // cleared: no surface there
            samples.push_back({glm::vec3(position[x]), glm::vec3(normal[x])});
        }
    }
    return samples;
}

} // namespace gi::vpl
