#include "gi/vpl/ReflectiveShadowMapPass.h"

#include "gl/RenderTarget.h"
#include "gl/Shared.h"

#include <cstdio>

namespace gi::vpl {

bool ReflectiveShadowMapPass::init(gl::ShaderLibrary& shaders, std::string& error) {
    mDepthProgram = shaders.build({"vpl/rsm_depth",
            {{GL_VERTEX_SHADER, "vpl/rsm.vert"}, {GL_FRAGMENT_SHADER, "common/depth_only.frag"}},
            {}}, error);
    if (!mDepthProgram) return false;
    mProgram = shaders.build({"vpl/rsm",
            {{GL_VERTEX_SHADER, "vpl/rsm.vert"}, {GL_FRAGMENT_SHADER, "vpl/rsm.frag"}}, {}},
            error);
    return bool(mProgram);
}

bool ReflectiveShadowMapPass::allocate(int resolution) {
    if (resolution == mResolution) return true;
    const glm::ivec2 size(resolution);
    mPosition = gl::createTexture2D(GL_RGBA32F, size, 1, "vpl/rsm_position");
    mNormal = gl::createTexture2D(GL_RGBA16F, size, 1, "vpl/rsm_normal");
    mFlux = gl::createTexture2D(GL_RGBA32F, size, 1, "vpl/rsm_flux");
    mDepth = gl::createTexture2D(GL_DEPTH_COMPONENT32F, size, 1, "vpl/rsm_depth");
    std::string error;
    if (!gl::attachFramebuffer(mFramebuffer, "vpl/rsm", {&mPosition, &mNormal, &mFlux}, &mDepth,
                error)) {
        std::fprintf(stderr, "vpl: %s\n", error.c_str());
        mResolution = 0;
        return false;
    }
    mResolution = resolution;
    return true;
}

void ReflectiveShadowMapPass::drawView(const scene::GpuScene& scene, const scene::LightView& view) const {
    const glm::vec4 axis(view.axis, view.orthographic ? 1.0f : 0.0f);
    for (const GLuint program : {mDepthProgram.id(), mProgram.id()}) {
        glProgramUniformMatrix4fv(program, LOC_RSM_VIEW_PROJECTION, 1, GL_FALSE,
                &view.viewProjection[0][0]);
    }
    glProgramUniform4fv(mProgram.id(), LOC_RSM_AXIS, 1, &axis[0]);
    glProgramUniform1f(mProgram.id(), LOC_RSM_FOOTPRINT, view.footprint);
    glProgramUniform1i(mProgram.id(), LOC_RSM_LIGHT, view.light);
    const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    const float far = 1.0f;
    for (int i = 0; i < 3; ++i) glClearNamedFramebufferfv(mFramebuffer.id(), GL_COLOR, i, zero);
    glDepthMask(GL_TRUE);
    glClearNamedFramebufferfv(mFramebuffer.id(), GL_DEPTH, 0, &far);
    // An area light does not see its own emitting surfaces (its centre may lie inside them).
    const auto set = view.areaLight ? scene::GpuScene::DrawSet::NotEmittingLight
                                    : scene::GpuScene::DrawSet::All;
    glDepthFunc(GL_LESS);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glUseProgram(mDepthProgram.id());
    scene.drawAll(mDepthProgram.id(), false, nullptr, set);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDepthFunc(GL_LEQUAL);
    glDepthMask(GL_FALSE);
    glUseProgram(mProgram.id());
    scene.drawAll(mProgram.id(), false, nullptr, set);
    glDepthMask(GL_TRUE);
    glDepthFunc(GL_LESS);
}

void ReflectiveShadowMapPass::readBack(int light, std::vector<RsmTexel>& texels) const {
    const std::size_t count = std::size_t(mResolution) * std::size_t(mResolution);
    std::vector<glm::vec4> position(count), normal(count), flux(count);
    const auto bytes = GLsizei(count * sizeof(glm::vec4));
    glGetTextureImage(mPosition.id(), 0, GL_RGBA, GL_FLOAT, bytes, position.data());
    glGetTextureImage(mNormal.id(), 0, GL_RGBA, GL_FLOAT, bytes, normal.data());
    glGetTextureImage(mFlux.id(), 0, GL_RGBA, GL_FLOAT, bytes, flux.data());
    for (std::size_t i = 0; i < count; ++i) {
        if (position[i].w <= 0.0f) continue;
        const glm::vec3 f(flux[i]);
        if (!(f.r + f.g + f.b > 0.0f)) continue;
        texels.push_back({glm::vec3(position[i]), glm::vec3(normal[i]), f, flux[i].a, light});
    }
}

std::vector<RsmTexel> ReflectiveShadowMapPass::execute(const scene::GpuScene& scene,
        const std::vector<scene::LightView>& views, int resolution, bool gltfReflectance,
        gl::GpuProfiler& profiler) {
    std::vector<RsmTexel> texels;
    if (views.empty() || !allocate(resolution)) return texels;
    gl::GpuScope scope(profiler, "vpl/rsm");
    glBindFramebuffer(GL_FRAMEBUFFER, mFramebuffer.id());
    glViewport(0, 0, mResolution, mResolution);
    glEnable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glDisable(GL_BLEND);
    scene.bindLights();
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BIND_SSBO_MATERIALS, scene.materialBuffer().id());
    glProgramUniform1i(mProgram.id(), LOC_RSM_GLTF, gltfReflectance ? 1 : 0);
    for (const scene::LightView& view : views) {
        drawView(scene, view);
        readBack(view.light, texels);
    }
    glDisable(GL_DEPTH_TEST);
    glUseProgram(0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return texels;
}

} // namespace gi::vpl
