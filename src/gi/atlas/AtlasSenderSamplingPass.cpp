#include "gi/atlas/AtlasSenderSamplingPass.h"

#include "gl/Shared.h"

namespace gi::atlas {
namespace {

GLuint groupsFor(std::size_t invocations) {
    return GLuint((invocations + ATLAS_SENDER_LOCAL_SIZE - 1) / ATLAS_SENDER_LOCAL_SIZE);
}

std::size_t blocksPerRow(int resolution) {
    return std::size_t((resolution + ATLAS_SENDER_BLOCK - 1) / ATLAS_SENDER_BLOCK);
}

} // namespace

bool AtlasSenderSamplingPass::init(gl::ShaderLibrary& shaders, std::string& error) {
    const auto build = [&](const char* name, const char* step) {
        return shaders.build({name, {{GL_COMPUTE_SHADER, "atlas/sender_sampling.comp"}}, {step}},
                error);
    };
    mRows = build("atlas/sender_sampling_rows", "STEP_ROWS");
    if (!mRows) return false;
    mPrefix = build("atlas/sender_sampling_prefix", "STEP_PREFIX");
    if (!mPrefix) return false;
    mPool = build("atlas/sender_sampling_pool", "STEP_POOL");
    return bool(mPool);
}

void AtlasSenderSamplingPass::execute(const Inputs& in, gl::GpuProfiler& profiler) {
    gl::GpuScope scope(profiler, "atlas/sender_sampling");
    const int r = in.textures.resolution;
    const int samples = in.samples;
    bool table = in.rebuildTable;
    if (r != mResolution) {
        mResolution = r;
        mRowPower = gl::createBuffer(std::size_t(r) * sizeof(float), nullptr, 0,
                "atlas/sender_sampling_rows");
        mBlockPower = gl::createBuffer(std::size_t(r) * blocksPerRow(r) * sizeof(float), nullptr,
                0, "atlas/sender_sampling_blocks");
        table = true;
    }
    if (samples != mSamples) {
        mSamples = samples;
        mPoints = gl::createBuffer(std::size_t(samples) * ATLAS_POOL_STRIDE * sizeof(GLuint),
                nullptr, 0, "atlas/sender_sampling_pool");
    }
    glBindBufferBase(GL_UNIFORM_BUFFER, BIND_UBO_ATLAS, in.atlasUniforms.id());
    glBindTextureUnit(BIND_TEX_ATLAS_DIRECT, in.textures.senderRadiance(in.bounce).id());
    glBindTextureUnit(BIND_TEX_ATLAS_DIRECT_BACK, in.textures.senderRadianceBack(in.bounce).id());
    glBindTextureUnit(BIND_TEX_ATLAS_NORMAL, in.textures.normal.id());
    glBindTextureUnit(BIND_TEX_ATLAS_POSITION, in.textures.position.id());
    bind();
    if (table) {
        glUseProgram(mRows.id());
        glDispatchCompute(groupsFor(std::size_t(r)), 1, 1);
        // Consumer: the prefix step reads the row sums.
        glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
        glUseProgram(mPrefix.id());
        glDispatchCompute(1, 1, 1);
        // Consumer: the pool step reads the prefix sums.
        glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    }
    glUseProgram(mPool.id());
    glDispatchCompute(groupsFor(std::size_t(samples) * ATLAS_POOL_STRIDE), 1, 1);
    // Consumer: the gather's fragment shader reads the pool and the total power.
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    glUseProgram(0);
}

void AtlasSenderSamplingPass::bind() const {
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BIND_SSBO_ATLAS_SENDER_ROWS, mRowPower.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BIND_SSBO_ATLAS_SENDER_BLOCKS, mBlockPower.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BIND_SSBO_ATLAS_SENDER_POOL, mPoints.id());
}

} // namespace gi::atlas
