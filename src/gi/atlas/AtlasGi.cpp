#include "gi/atlas/AtlasGi.h"

#include "gi/atlas/Hammersley.h"
#include "gl/Limits.h"

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cstdio>
#include <memory>

namespace gi::atlas {
namespace {

bool sameLights(const std::vector<scene::Light>& a, const std::vector<scene::Light>& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i) {
        const scene::Light& x = a[i];
        const scene::Light& y = b[i];
        if (x.type != y.type || x.position != y.position || x.direction != y.direction ||
                x.color != y.color || x.intensity != y.intensity || x.range != y.range ||
                x.innerConeAngle != y.innerConeAngle || x.outerConeAngle != y.outerConeAngle) {
            return false;
        }
    }
    return true;
}

int atlasView(DebugView view) {
    switch (view) {
    case DebugView::AtlasDirect: return ATLAS_VIEW_DIRECT;
    case DebugView::AtlasNormal: return ATLAS_VIEW_NORMAL;
    case DebugView::AtlasPosition: return ATLAS_VIEW_POSITION;
    case DebugView::AtlasAlbedo: return ATLAS_VIEW_ALBEDO;
    case DebugView::AtlasIndirect: return ATLAS_VIEW_INDIRECT;
    case DebugView::AtlasCharts: return ATLAS_VIEW_CHARTS;
    default: return -1;
    }
}

} // namespace

bool AtlasGi::init(gl::ShaderLibrary& shaders, const scene::Scene& scene, std::string& error) {
    mMesh = flattenScene(scene);
    mFollowsPose = std::any_of(scene.instances.begin(), scene.instances.end(),
            [](const scene::Instance& instance) { return instance.dynamic; });
    mUniforms = gl::createBuffer(
            sizeof(shader::AtlasUniforms), nullptr, GL_DYNAMIC_STORAGE_BIT, "atlas/uniforms");
    return mPose.init(shaders, error) && mGBuffer.init(shaders, error) &&
            mSenderSampling.init(shaders, error) &&
            mGather.init(shaders, error) && mDilate.init(shaders, error) &&
            mResolve.init(shaders, error) && mDebugView.init(shaders, error);
}

bool AtlasGi::buildAtlasGeometry(std::string& error) {
    if (mMesh.triangleCount() == 0) {
        // Nothing to light and nothing to bounce from: the frame is direct light (if any).
        mAtlas = Atlas{};
        std::fprintf(stderr, "atlas: the scene has no triangles; atlas GI adds nothing\n");
        return true;
    }
    AtlasOptions options;
    options.resolution = mSettings.resolution;
    options.gutter = mSettings.gutter;
    std::unique_ptr<AtlasCache> cache;
    if (mSettings.cache) cache = std::make_unique<AtlasCache>(AtlasCache::defaultDirectory());
    Atlas atlas;
    AtlasBuildInfo info;
    if (!loadOrBuildAtlas(mMesh, options, cache.get(), atlas, info, error)) return false;
    mAtlas = std::move(atlas);
    mBuildInfo = std::move(info);
    std::fprintf(stderr,
            "atlas: %zu charts for %zu triangles in %d^2 texels, texel %.4g m, %s %.3f s%s%s\n",
            mAtlas.charts.size(), mAtlas.triangleCount(), mAtlas.resolution, mAtlas.texelSize,
            mBuildInfo.cacheHit ? "loaded from the cache in" : "built in", mBuildInfo.seconds,
            mAtlas.fromTexcoord1 ? " (the scene's TEXCOORD_1)" : "",
            mBuildInfo.cacheError.empty()
                    ? ""
                    : (" (not cached: " + mBuildInfo.cacheError + ")").c_str());
    mGeometry.upload(mMesh, mAtlas, mFollowsPose);
    mPosedGeometry = ~std::uint64_t(0);
    mTextures.allocate(mSettings.resolution);
    return mGBuffer.attach(mTextures, error) && mGather.attach(mTextures, error) &&
            mDilate.attach(mTextures, error);
}

bool AtlasGi::configure(const Settings& settings, std::string& error) {
    const AtlasSettings& s = settings.atlas;
    GLint maxTexture = 0, maxViewport[2] = {0, 0};
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxTexture);
    glGetIntegerv(GL_MAX_VIEWPORT_DIMS, maxViewport);
    const int largest = std::min(maxTexture, std::min(maxViewport[0], maxViewport[1]));
    if (s.resolution > largest) {
        error = "atlas.resolution " + std::to_string(s.resolution) +
                " exceeds the largest texture / viewport " + std::to_string(largest);
        return false;
    }
    if (!gl::fitsResourceBudget("atlas.resolution " + std::to_string(s.resolution) +
                    " (atlas layers)", AtlasTextures::memoryFor(s.resolution), error)) {
        return false;
    }
    if (s.samples > maxTexture) {
        error = "atlas.samples " + std::to_string(s.samples) + " exceeds GL_MAX_TEXTURE_SIZE " +
                std::to_string(maxTexture);
        return false;
    }
    const bool rebuild =
            !mConfigured || s.resolution != mSettings.resolution || s.gutter != mSettings.gutter;
    const bool resample = !mConfigured || s.samples != mSettings.samples;
    const bool changed = !mConfigured || !(s == mSettings) || !(settings.shadow == mShadowSettings);
    const AtlasSettings previous = mSettings;
    mSettings = s;
    if (rebuild && !buildAtlasGeometry(error)) {
        mSettings = previous;
        return false;
    }
    if (resample) {
        const std::vector<glm::vec2> points = hammersley(s.samples);
        mSamples = gl::createTexture2D(GL_RG32F, {s.samples, 1}, 1, "atlas/samples");
        glTextureSubImage2D(mSamples.id(), 0, 0, 0, s.samples, 1, GL_RG, GL_FLOAT, points.data());
    }
    mShadowSettings = settings.shadow;
    mConfigured = true;
    if (changed) {
        mGBufferValid = false;
        mSamplesDone = 0;
        mSetIndex = 0;
        mFrameIndex = 0;
        mWarnedNoOccupancy = false;
    }
    return true;
}

void AtlasGi::writeUniforms() {
    shader::AtlasUniforms& u = mUniformData;
    u.size.x = mSettings.resolution;
    u.size.y = mSettings.samples;
    u.size.z = mSettings.estimator;
    // The area estimator's 1/r^2 stops growing within two texel edges of the receiver.
    u.sampling.z = mSettings.estimator == ATLAS_ESTIMATOR_AREA
                           ? float(4.0 * mAtlas.texelSize * mAtlas.texelSize)
                           : 2.0f * glm::pi<float>();
    u.sampling.w = mSamplesDone > 0 ? 1.0f / float(mSamplesDone) : 0.0f;
    u.dilation = glm::vec4(float((mSettings.gutter + 1) / 2), 0.0f, 0.0f, 0.0f);
    glNamedBufferSubData(mUniforms.id(), 0, sizeof u, &u);
}

bool AtlasGi::inputsChanged(const GiFrameInputs& in) {
    // Moving instances move their shadows, so the G-buffer's direct light changes.
    const bool changed = mScene != &in.scene || !sameLights(mLights, in.lights) ||
                         mGeometryVersion != in.scene.geometryVersion();
    mScene = &in.scene;
    mGeometryVersion = in.scene.geometryVersion();
    if (changed) mLights = in.lights;
    return changed;
}

void AtlasGi::update(const GiFrameInputs& in, gl::GpuProfiler& profiler) {
    if (mMesh.triangleCount() == 0) return;
    if (mFollowsPose && mPosedGeometry != in.scene.geometryVersion()) {
        mPose.execute(in.scene, mGeometry, profiler);
        mPosedGeometry = in.scene.geometryVersion();
    }
    if (inputsChanged(in) || !mSettings.progressive) mGBufferValid = false;
    const OccupancyVolume* occupancy =
            mSettings.visibility == ATLAS_VISIBILITY_VOXEL ? in.occupancy : nullptr;
    if (mSettings.visibility == ATLAS_VISIBILITY_VOXEL && !in.occupancy && !mWarnedNoOccupancy) {
        std::fprintf(stderr,
                "atlas: atlas.visibility=voxel needs a voxel occupancy volume and "
                "this frame has none; senders are not occluded\n");
        mWarnedNoOccupancy = true;
    }
    // Visibility changes whenever the occupancy is recomputed (it moved, or geometry did).
    if ((occupancy != nullptr) != mHadOccupancy ||
            (occupancy && occupancy->version != mOccupancyVersion)) {
        mSamplesDone = 0;
    }
    mHadOccupancy = occupancy != nullptr;
    mOccupancyVersion = occupancy ? occupancy->version : 0;

    if (!mGBufferValid) {
        writeUniforms();
        mGBuffer.execute({in.scene, mGeometry, in.shadows, in.frameUniforms, mUniforms},
                {mTextures}, profiler);
        mGBufferValid = true;
        mSenderTableValid = false;
        mSamplesDone = 0;
    }
    if (mSamplesDone == 0) mSetIndex = 0;
    const bool gather = !mSettings.progressive || mSamplesDone == 0 ||
            (mSettings.rotate && mSamplesDone < mSettings.targetSamples);
    if (gather) {
        if (!mSettings.progressive) mSamplesDone = 0;
        if (mSamplesDone == 0) mGather.clear();
        const std::uint32_t set = mSettings.progressive ? mSetIndex : mFrameIndex;
        const glm::vec2 offset = mSettings.rotate ? cranleyPattersonOffset(set) : glm::vec2(0.0f);
        mUniformData.sampling.x = offset.x;
        mUniformData.sampling.y = offset.y;
        writeUniforms();
        if (mSettings.estimator == ATLAS_ESTIMATOR_AREA) {
            mSenderSampling.execute(
                    mTextures, mUniforms, mSettings.samples, !mSenderTableValid, profiler);
            mSenderTableValid = true;
        }
        mGather.execute({mTextures, mSamples, mUniforms, occupancy, mSenderSampling}, profiler);
        mSamplesDone += mSettings.samples;
        ++mSetIndex;
        writeUniforms();
        mDilate.execute(mTextures, mUniforms, profiler);
    }
    ++mFrameIndex;

    mResolve.resize(in.outputSize);
    mResolve.execute({in.scene, mGeometry, in.frameUniforms, mUniforms, mTextures}, profiler);

    const int view = atlasView(in.debugView);
    mShowDebug = view >= 0;
    if (mShowDebug) {
        mUniformData.size.w = view;
        writeUniforms();
        mDebugView.execute({in.scene, mGeometry, in.frameUniforms, mUniforms, mTextures},
                in.outputSize, profiler);
    }
}

GiOutputs AtlasGi::outputs() const {
    GiOutputs out;
    if (mMesh.triangleCount() == 0) return out;
    out.indirect = &mResolve.indirect();
    out.size = mResolve.size();
    out.debugImage = mShowDebug ? &mDebugView.image() : nullptr;
    return out;
}

} // namespace gi::atlas

namespace gi::atlas {

std::string AtlasGi::status() const {
    return "atlas " + std::to_string(mSettings.resolution) + "^2, " +
           std::to_string(accumulatedSamples()) + " samples accumulated" +
           (mSettings.progressive ? " of " + std::to_string(mSettings.targetSamples) : "");
}

} // namespace gi::atlas
