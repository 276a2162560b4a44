#include "gi/voxel/InjectPass.h"

#include "gl/Shared.h"

#include <algorithm>
#include <cmath>

namespace gi::voxel {
namespace {

// Region injection has to reach: the scene inside the coarsest level.
scene::Aabb injectionRegion(const CascadeVolume& volume, const scene::Aabb& sceneBounds) {
    const int coarsest = volume.levels() - 1;
    scene::Aabb region;
    region.extend(volume.origin(coarsest));
    region.extend(volume.origin(coarsest) + glm::vec3(volume.extent(coarsest)));
    if (!sceneBounds.empty()) {
        region.min = glm::max(region.min, sceneBounds.min);
        region.max = glm::min(region.max, sceneBounds.max);
    }
    return region;
}

} // namespace

std::vector<LightView> injectionViews(const std::vector<scene::Light>& lights,
        const CascadeVolume& volume, const scene::Aabb& sceneBounds, int resolution) {
    const scene::Aabb region = injectionRegion(volume, sceneBounds);
    return scene::lightViews(lights, region, resolution);
}

double fluxSumScale(const std::vector<scene::Light>& lights, const std::vector<LightView>& views,
        int resolution, float finestVoxel, float exposure) {
    // How much larger than lightStrength x footprint a fragment's share may be: the glTF
    // BRDF's reflectance of light from one angle over its reflectance of uniform light
    // (voxel_reflectance.glsl) stays well under it.
    constexpr double kReflectanceHeadroom = 8.0;
    constexpr double kLargestSum = 2147483648.0;   // 2^31: half of what an R32UI holds
    const double pixels = double(resolution) * double(resolution);
    double bound = 0.0;
    for (const LightView& view : views) {
        bound += scene::lightStrength(lights.at(std::size_t(view.light))) * double(view.footprint) *
                 pixels;
    }
    bound *= kReflectanceHeadroom * double(exposure) / (double(finestVoxel) * double(finestVoxel));
    if (!(bound > 0.0) || !std::isfinite(bound)) return 1.0;
    // A power of two, so that the units divide out exactly; within a float's range.
    return std::exp2(std::clamp(std::floor(std::log2(kLargestSum / bound)), -100.0, 100.0));
}

bool InjectPass::init(gl::ShaderLibrary& shaders, std::string& error) {
    mDepthProgram = shaders.build({"voxel/inject_depth",
            {{GL_VERTEX_SHADER, "voxel/inject.vert"}, {GL_FRAGMENT_SHADER, "common/depth_only.frag"}},
            {}}, error);
    if (!mDepthProgram) return false;
    mInjectProgram = shaders.build({"voxel/inject",
            {{GL_VERTEX_SHADER, "voxel/inject.vert"}, {GL_FRAGMENT_SHADER, "voxel/inject.frag"}},
            {}}, error);
    if (!mInjectProgram) return false;
    mFinalizeProgram = shaders.build({"voxel/inject_finalize",
            {{GL_COMPUTE_SHADER, "voxel/inject_finalize.comp"}}, {}}, error);
    return bool(mFinalizeProgram);
}

void InjectPass::setView(const LightView& view, std::size_t ordinal, double fluxScale) const {
    const glm::vec4 axis(view.axis, view.orthographic ? 1.0f : 0.0f);
    for (const GLuint program : {mDepthProgram.id(), mInjectProgram.id()}) {
        glProgramUniformMatrix4fv(program, LOC_INJECT_VIEW_PROJECTION, 1, GL_FALSE,
                &view.viewProjection[0][0]);
    }
    glProgramUniform4fv(mInjectProgram.id(), LOC_INJECT_AXIS, 1, &axis[0]);
    glProgramUniform1f(mInjectProgram.id(), LOC_INJECT_FOOTPRINT, view.footprint);
    glProgramUniform1i(mInjectProgram.id(), LOC_INJECT_LIGHT, view.light);
    glProgramUniform2f(mInjectProgram.id(), LOC_INJECT_FLUX_SUM, float(fluxScale), float(ordinal));
}

void InjectPass::finalize(const Inputs& in, const VoxelTextures& t, gl::GpuProfiler& profiler) {
    gl::GpuScope scope(profiler, "voxel/finalize");
    const glm::ivec3 size(t.resolution, t.resolution, t.resolution * t.levels);
    const glm::ivec3 groups = (size + VOXEL_LOCAL_SIZE - 1) / VOXEL_LOCAL_SIZE;
    glUseProgram(mFinalizeProgram.id());
    glBindBufferBase(GL_UNIFORM_BUFFER, BIND_UBO_VOXEL, in.voxelUniforms.id());
    glBindImageTexture(BIND_IMG_VOXEL_HELPER, t.helper.id(), 0, GL_TRUE, 0, GL_READ_WRITE, GL_RGBA16F);
    glBindImageTexture(BIND_IMG_VOXEL_IRRADIANCE, t.irradiance.id(), 0, GL_TRUE, 0, GL_READ_WRITE, GL_RGBA16F);
    glBindImageTexture(BIND_IMG_VOXEL_ALBEDO, t.albedo.id(), 0, GL_TRUE, 0, GL_READ_WRITE, GL_RGBA16F);
    glBindImageTexture(BIND_IMG_VOXEL_FLUX_SUM, t.fluxSum.id(), 0, GL_TRUE, 0, GL_READ_WRITE, GL_R32UI);
    glProgramUniform2f(mFinalizeProgram.id(), LOC_INJECT_FLUX_SUM, float(in.fluxScale), 0.0f);
    glDispatchCompute(GLuint(groups.x), GLuint(groups.y), GLuint(groups.z));
    // Consumers: the next light's injection (helper) and propagation (irradiance).
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
}

void InjectPass::execute(const Inputs& in, const Outputs& out, gl::GpuProfiler& profiler) {
    mTarget.resize({in.resolution, in.resolution});
    const VoxelTextures& t = out.textures;
    if (!in.fragmentMean) {
        // The flux sums start at zero once, before the first light (even when there is none:
        // finalize reads them); finalize reads but keeps them.
        gl::GpuScope scope(profiler, "voxel/inject");
        glClearTexImage(t.fluxSum.id(), 0, GL_RED_INTEGER, GL_UNSIGNED_INT, nullptr);
    }
    std::size_t next = 0;
    while (next < in.views.size()) {
        const int light = in.views[next].light;
        {
            gl::GpuScope scope(profiler, "voxel/inject");
            // Each light averages its own fragments: counts restart at zero.
            glClearTexImage(t.lock.id(), 0, GL_RED_INTEGER, GL_UNSIGNED_INT, nullptr);
            mTarget.bind();
            glDisable(GL_CULL_FACE);
            glDisable(GL_BLEND);
            glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
            glEnable(GL_DEPTH_TEST);
            glBindBufferBase(GL_UNIFORM_BUFFER, BIND_UBO_VOXEL, in.voxelUniforms.id());
            in.scene.bindLights();
            glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BIND_SSBO_MATERIALS, in.scene.materialBuffer().id());
            glBindImageTexture(BIND_IMG_VOXEL_HELPER, t.helper.id(), 0, GL_TRUE, 0, GL_READ_WRITE, GL_RGBA16F);
            glBindImageTexture(BIND_IMG_VOXEL_LOCK, t.lock.id(), 0, GL_TRUE, 0, GL_READ_WRITE, GL_R32UI);
            glBindImageTexture(BIND_IMG_VOXEL_FLUX_SUM, t.fluxSum.id(), 0, GL_TRUE, 0, GL_READ_WRITE,
                    GL_R32UI);
            if (t.anisotropic) {
                glBindImageTexture(BIND_IMG_VOXEL_DIRECTIONAL, t.directional.id(), 0, GL_TRUE, 0,
                        GL_READ_WRITE, GL_RGBA16F);
            }
            for (; next < in.views.size() && in.views[next].light == light; ++next) {
                setView(in.views[next], next, in.fluxScale);
                mTarget.clear();
                glDepthFunc(GL_LESS);
                glUseProgram(mDepthProgram.id());
                const auto set = in.views[next].areaLight ? scene::GpuScene::DrawSet::NotEmittingLight
                                                          : scene::GpuScene::DrawSet::All;
                in.scene.drawAll(mDepthProgram.id(), false, nullptr, set);
                glDepthFunc(GL_LEQUAL);
                glDepthMask(GL_FALSE);
                glUseProgram(mInjectProgram.id());
                in.scene.drawAll(mInjectProgram.id(), false, nullptr, set);
                // Consumer: the next view of this light continues the same running averages.
                glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
            }
            glDepthMask(GL_TRUE);
            glDisable(GL_DEPTH_TEST);
            glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
            glBindFramebuffer(GL_FRAMEBUFFER, 0);
        }
        if (in.fragmentMean) finalize(in, t, profiler);
    }
    if (!in.fragmentMean) finalize(in, t, profiler);
    glUseProgram(0);
}

} // namespace gi::voxel
