#include "gi/atlas/AtlasSenderSamplingPass.h"

#include "gl/Shared.h"

#include <glm/glm.hpp>

#include <algorithm>

namespace gi::atlas {
namespace {

GLuint groupsFor(std::size_t invocations) {
    return GLuint((invocations + ATLAS_SENDER_LOCAL_SIZE - 1) / ATLAS_SENDER_LOCAL_SIZE);
}

constexpr std::size_t kViewCells =
        std::size_t(ATLAS_VIEW_SAMPLES_PER_SIDE) * ATLAS_VIEW_SAMPLES_PER_SIDE;
constexpr std::size_t kSurfaceCells = ATLAS_SURFACE_POINTS;
static_assert(sizeof(SurfacePoint) == SURFACE_POINT_UINTS * sizeof(std::uint32_t));

std::size_t blocksPerRow(int resolution) {
    return std::size_t((resolution + ATLAS_SENDER_BLOCK - 1) / ATLAS_SENDER_BLOCK);
}

} // namespace

bool AtlasSenderSamplingPass::drawsByImportance(const AtlasSettings& settings) {
    return settings.importance != ATLAS_IMPORTANCE_POWER &&
           settings.estimator == ATLAS_ESTIMATOR_AREA;
}

std::vector<gl::MemoryItem> AtlasSenderSamplingPass::importanceMemoryFor(
        const AtlasSettings& settings, int resolution) {
    if (!drawsByImportance(settings)) return {};
    return {{"atlas/importance", gl::textureBytes(GL_RG32F, {resolution, resolution, 1}, 1)},
            {"atlas/receivers", std::max(kViewCells, kSurfaceCells) * 2 * sizeof(glm::vec4)},
            {"atlas/surface_points", kSurfaceCells * sizeof(SurfacePoint)}};
}

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
    if (!mPool) return false;
    mViewSamples = build("atlas/sender_sampling_view_samples", "STEP_VIEW_SAMPLES");
    if (!mViewSamples) return false;
    mSurfaceSamples = build("atlas/sender_sampling_surface_samples", "STEP_SURFACE_SAMPLES");
    if (!mSurfaceSamples) return false;
    mImportance = build("atlas/sender_sampling_importance", "STEP_IMPORTANCE");
    if (!mImportance) return false;
    constexpr std::size_t kCells = std::max(kViewCells, kSurfaceCells);
    mReceivers = gl::createBuffer(kCells * 2 * sizeof(glm::vec4), nullptr, 0,
            "atlas/receivers");
    reserveImportance(0);
    setSurfacePoints({});
    return true;
}

void AtlasSenderSamplingPass::execute(const Inputs& in, gl::GpuProfiler& profiler) {
    gl::GpuScope scope(profiler, "atlas/sender_sampling");
    const int r = in.textures.resolution;
    const int samples = in.samples;
    bool table = in.rebuildTable;
    if (r != mResolution) {
        mResolution = r;
        mRowPower = gl::createBuffer(std::size_t(r) * sizeof(glm::vec2), nullptr, 0,
                "atlas/sender_sampling_rows");
        mBlockPower = gl::createBuffer(std::size_t(r) * blocksPerRow(r) * sizeof(glm::vec2),
                nullptr, 0, "atlas/sender_sampling_blocks");
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
    glBindTextureUnit(BIND_TEX_ATLAS_IMPORTANCE, mImportanceLayer.id());
}

void AtlasSenderSamplingPass::reserveImportance(int resolution) {
    if (resolution == mImportanceResolution && mImportanceLayer) return;
    mImportanceResolution = resolution;
    if (resolution > 0) {
        mImportanceLayer =
                gl::createTexture2D(GL_RG32F, {resolution, resolution}, 1, "atlas/importance");
        return;
    }
    mImportanceLayer = gl::createTexture2D(GL_RG32F, {1, 1}, 1, "atlas/importance_none");
    const float none[2] = {0.0f, 0.0f};
    glTextureSubImage2D(mImportanceLayer.id(), 0, 0, 0, 1, 1, GL_RG, GL_FLOAT, none);
}

void AtlasSenderSamplingPass::takeViewSamples(const gl::Texture& viewIndirect,
        const gl::Buffer& frameUniforms, gl::GpuProfiler& profiler) {
    gl::GpuScope scope(profiler, "atlas/view_samples");
    glBindBufferBase(GL_UNIFORM_BUFFER, BIND_UBO_FRAME, frameUniforms.id());
    glBindTextureUnit(BIND_TEX_INDIRECT, viewIndirect.id());
    writeReceivers(mViewSamples, kViewCells);
}

void AtlasSenderSamplingPass::setSurfacePoints(const SurfacePoints& points) {
    mSurfacePointCount = int(std::min(points.points.size(), kSurfaceCells));
    const std::size_t bytes = std::max<std::size_t>(
            std::size_t(mSurfacePointCount) * sizeof(SurfacePoint), sizeof(SurfacePoint));
    mSurfacePoints = gl::createBuffer(bytes, nullptr, GL_DYNAMIC_STORAGE_BIT,
            "atlas/surface_points");
    if (mSurfacePointCount > 0) {
        glNamedBufferSubData(mSurfacePoints.id(), 0,
                GLsizeiptr(std::size_t(mSurfacePointCount) * sizeof(SurfacePoint)),
                points.points.data());
    }
}

void AtlasSenderSamplingPass::takeSurfaceSamples(const gl::Buffer& sceneVertices,
        const gl::Buffer& atlasUniforms, gl::GpuProfiler& profiler) {
    gl::GpuScope scope(profiler, "atlas/surface_samples");
    glBindBufferBase(GL_UNIFORM_BUFFER, BIND_UBO_ATLAS, atlasUniforms.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BIND_SSBO_SCENE_VERTICES, sceneVertices.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BIND_SSBO_ATLAS_SURFACE_POINTS,
            mSurfacePoints.id());
    writeReceivers(mSurfaceSamples, std::size_t(mSurfacePointCount));
}

void AtlasSenderSamplingPass::writeReceivers(const gl::ProgramRef& program, std::size_t cells) {
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BIND_SSBO_ATLAS_RECEIVERS, mReceivers.id());
    glUseProgram(program.id());
    glDispatchCompute(groupsFor(cells), 1, 1);
    // Consumer: the importance step reads the receivers.
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    glUseProgram(0);
    mReceiverCells = int(cells);
}

void AtlasSenderSamplingPass::computeImportance(const AtlasTextures& textures,
        const gl::Buffer& atlasUniforms, gl::GpuProfiler& profiler) {
    gl::GpuScope scope(profiler, "atlas/importance");
    const int r = textures.resolution;
    reserveImportance(r);
    glBindBufferBase(GL_UNIFORM_BUFFER, BIND_UBO_ATLAS, atlasUniforms.id());
    glBindTextureUnit(BIND_TEX_ATLAS_DIRECT, textures.direct.id());
    glBindTextureUnit(BIND_TEX_ATLAS_DIRECT_BACK, textures.directBack.id());
    glBindTextureUnit(BIND_TEX_ATLAS_NORMAL, textures.normal.id());
    glBindTextureUnit(BIND_TEX_ATLAS_POSITION, textures.position.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BIND_SSBO_ATLAS_RECEIVERS, mReceivers.id());
    glBindImageTexture(BIND_IMG_ATLAS_IMPORTANCE, mImportanceLayer.id(), 0, GL_FALSE, 0,
            GL_WRITE_ONLY, GL_RG32F);
    glUseProgram(mImportance.id());
    // A row of texels per y: r^2 / 64 groups in x alone exceed GL's 65535 at r = 4096.
    glDispatchCompute(groupsFor(std::size_t(r)), GLuint(r), 1);
    // Consumers: the table's rows and the gather fetch the layer.
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
    glUseProgram(0);
}

std::vector<glm::vec4> AtlasSenderSamplingPass::readReceivers() const {
    std::vector<glm::vec4> samples(std::size_t(2) * std::size_t(mReceiverCells));
    glGetNamedBufferSubData(mReceivers.id(), 0, GLsizeiptr(samples.size() * sizeof(glm::vec4)),
            samples.data());
    return samples;
}

} // namespace gi::atlas
