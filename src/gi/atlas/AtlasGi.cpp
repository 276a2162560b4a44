#include "gi/atlas/AtlasGi.h"

#include "gi/atlas/Hammersley.h"
#include "gl/Limits.h"

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cstdio>
#include <memory>

namespace gi::atlas {
namespace {

// Directions each receiver casts towards the sky per sample set (gather.frag skyIrradiance):
// sets accumulate, so a still view converges whatever this is; more only costs time.
constexpr int kSkyDirectionsPerSet = 16;

// atlas.importance: the share of the mean importance every lit texel keeps in the senders'
// draw whatever its receivers see (sender_weight.glsl), as the VPLs' draw keeps
// (vpl::kViewIndependentShare): nothing the receivers miss is left out of the draw.
constexpr float kImportanceFloorShare = 0.1f;

// The sky's directions per set: none without a sky.
int skyDirections(const GiFrameInputs& in) {
    return scene::skyRadiance(in.lights) != glm::vec3(0.0f) ? kSkyDirectionsPerSet : 0;
}

// The atlas layers' memory, with the senders' importance layer when the draw uses it.
std::vector<gl::MemoryItem> atlasMemoryFor(const AtlasSettings& s, bool backSides, int bounces) {
    std::vector<gl::MemoryItem> items = AtlasTextures::memoryFor(s.resolution, backSides, bounces);
    for (gl::MemoryItem& item : AtlasSenderSamplingPass::importanceMemoryFor(s, s.resolution)) {
        items.push_back(std::move(item));
    }
    return items;
}

bool sameLights(const std::vector<scene::Light>& a, const std::vector<scene::Light>& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i) {
        const scene::Light& x = a[i];
        const scene::Light& y = b[i];
        if (x.type != y.type || x.position != y.position || x.direction != y.direction ||
                x.color != y.color || x.intensity != y.intensity || x.range != y.range ||
                x.innerConeAngle != y.innerConeAngle || x.outerConeAngle != y.outerConeAngle ||
                x.emitters != y.emitters) {
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
    mBackSides = AtlasTextures::needsBackSides(scene);
    mFollowsPose = std::any_of(scene.instances.begin(), scene.instances.end(),
            [](const scene::Instance& instance) { return instance.dynamic; });
    mUniforms = gl::createBuffer(
            sizeof(shader::AtlasUniforms), nullptr, GL_DYNAMIC_STORAGE_BIT, "atlas/uniforms");
    return mPose.init(shaders, error) && mGBuffer.init(shaders, error) &&
            mSenderSampling.init(shaders, error) && mBounceSenders.init(shaders, error) &&
            mGather.init(shaders, error) && mDilate.init(shaders, error) &&
            mResolve.init(shaders, error) && mDebugViewPass.init(shaders, error);
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
    mSurfacePoints = surfacePoints(mMesh, ATLAS_SURFACE_POINTS);
    mSenderSampling.setSurfacePoints(mSurfacePoints);
    return allocateLayers(error);
}

bool AtlasGi::allocateLayers(std::string& error) {
    mTextures.allocate(mSettings.resolution, mBackSides, mBounces);
    return mGBuffer.attach(mTextures, error) && mGather.attach(mTextures, error) &&
            mDilate.attach(mTextures, error) && mBounceSenders.attach(mTextures, error);
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
                    " (atlas layers)",
                atlasMemoryFor(s, mBackSides, settings.giBounces), error)) {
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
    const bool relayer = !mConfigured || settings.giBounces != mBounces;
    const bool changed = !mConfigured || !(s == mSettings) ||
                         !(settings.shadow == mShadowSettings) || relayer ||
                         settings.glossyMaterials() != mGlossyMaterials;
    const AtlasSettings previous = mSettings;
    const int previousBounces = mBounces;
    mSettings = s;
    mBounces = settings.giBounces;
    if (rebuild ? !buildAtlasGeometry(error)
                : relayer && mMesh.triangleCount() > 0 && !allocateLayers(error)) {
        mSettings = previous;
        mBounces = previousBounces;
        return false;
    }
    if (resample) {
        const std::vector<glm::vec2> points = hammersley(s.samples);
        mSamples = gl::createTexture2D(GL_RG32F, {s.samples, 1}, 1, "atlas/samples");
        glTextureSubImage2D(mSamples.id(), 0, 0, 0, s.samples, 1, GL_RG, GL_FLOAT, points.data());
    }
    mShadowSettings = settings.shadow;
    mGlossyMaterials = settings.glossyMaterials();
    mConfigured = true;
    if (changed) {
        mContent.gBufferValid = false;
        mContent.samples = 0;
        mViewSampledFrom.reset();
        mViewSampleTakes = 0;
        mSurfaceSampleTakes = 0;
        mSenderSampling.reserveImportance(drawsByImportance() ? mSettings.resolution : 0);
        mImportanceReady = false;
        mFrameIndex = 0;
        mWarnedNoVisibility = false;
        mWarnedNoNearField = false;
    }
    return true;
}

void AtlasGi::writeUniforms(const FramePlan& plan, const GiFrameInputs& in) {
    shader::AtlasUniforms u{};
    u.size = glm::ivec4(mSettings.resolution, mSettings.samples, mSettings.estimator, plan.view);
    // The area estimator's 1/r^2 stops growing within two texel edges of the receiver.
    const float estimatorConstant = mSettings.estimator == ATLAS_ESTIMATOR_AREA
            ? float(4.0 * mAtlas.texelSize * mAtlas.texelSize)
            : 2.0f * glm::pi<float>();
    // The dilation normalises the sums as they are after this frame's gather.
    const float normalisation = mContent.samples > 0 ? 1.0f / float(mContent.samples) : 0.0f;
    u.sampling = glm::vec4(plan.rotation, estimatorConstant, normalisation);
    u.dilation = glm::vec4(float((mSettings.gutter + 1) / 2), mTextures.backSides ? 1.0f : 0.0f,
            mSettings.filter ? 1.0f : 0.0f, 0.0f);
    const glm::vec3 sky = scene::skyRadiance(in.lights) * in.scene.exposure();
    u.sky = glm::vec4(sky, float(skyDirections(in)));
    // The importance's receivers: the view's cells, whose kernel stops growing where the
    // estimator's does, or the points on the scene's surfaces, each standing for its share of
    // the surface, within which the kernel stops growing (else the texels nearest a point
    // would draw most of the samples).
    const bool bySurfaces = mSettings.importance == ATLAS_IMPORTANCE_SURFACES;
    const int cells = bySurfaces ? int(mSurfacePoints.points.size())
                                 : ATLAS_VIEW_SAMPLES_PER_SIDE * ATLAS_VIEW_SAMPLES_PER_SIDE;
    const float importanceClamp =
            bySurfaces ? float(mSurfacePoints.areaPerPoint) : estimatorConstant;
    u.importance = glm::vec4(drawsByImportance() && mImportanceReady ? kImportanceFloorShare : 0.0f,
            float(cells), mBounces > 1 ? 1.0f : 0.0f, importanceClamp);
    const double reach = double(mSettings.nearReach) * mAtlas.texelSize;
    u.nearField = glm::vec4(float(nearRays(in)), float(reach * reach), 0.0f, 0.0f);
    glNamedBufferSubData(mUniforms.id(), 0, sizeof u, &u);
}

bool AtlasGi::drawsByImportance() const {
    return AtlasSenderSamplingPass::drawsByImportance(mSettings);
}

const OccupancyVolume* AtlasGi::visibilityOccupancy(const GiFrameInputs& in) {
    if (mSettings.visibility != ATLAS_VISIBILITY_VOXEL) return nullptr;
    if (!in.occupancy && !mWarnedNoVisibility) {
        std::fprintf(stderr,
                "atlas: atlas.visibility=voxel needs a voxel occupancy volume and "
                "this frame has none; senders are not occluded\n");
        mWarnedNoVisibility = true;
    }
    return in.occupancy;
}

int AtlasGi::visibilityBvh(const GiFrameInputs& in) {
    if (mSettings.visibility != ATLAS_VISIBILITY_BVH) return 0;
    if (in.bvhRayIterations <= 0 && !mWarnedNoVisibility) {
        std::fprintf(stderr,
                "atlas: atlas.visibility=bvh needs the scene's BVH and this frame has none; "
                "senders are not occluded\n");
        mWarnedNoVisibility = true;
    }
    return in.bvhRayIterations;
}

int AtlasGi::nearRays(const GiFrameInputs& in) {
    if (mSettings.estimator != ATLAS_ESTIMATOR_AREA || mSettings.nearRays <= 0) return 0;
    if (in.bvhNodes <= 0) {
        if (!mWarnedNoNearField) {
            std::fprintf(stderr,
                    "atlas: atlas.near_rays needs the scene's BVH and this frame has none; the "
                    "area estimator counts the nearest senders, clamped\n");
            mWarnedNoNearField = true;
        }
        return 0;
    }
    return mSettings.nearRays;
}

AtlasGi::FramePlan AtlasGi::planFrame(const GiFrameInputs& in, const OccupancyVolume* occupancy) {
    Content& c = mContent;
    // Moving instances move their shadows, so the G-buffer's direct light changes.
    const bool inputsChanged = c.scene != &in.scene || !sameLights(c.lights, in.lights) ||
                               c.geometryVersion != in.scene.geometryVersion();
    if (inputsChanged) {
        c.scene = &in.scene;
        c.lights = in.lights;
        c.geometryVersion = in.scene.geometryVersion();
    }
    // Without progressive mode every frame is computed from scratch (the thesis).
    if (inputsChanged || !mSettings.progressive) c.gBufferValid = false;
    // Visibility changes whenever the occupancy is recomputed (it moved, or geometry did).
    const std::optional<std::uint64_t> visibility =
            occupancy ? std::optional<std::uint64_t>(occupancy->version) : std::nullopt;
    if (visibility != c.occupancyVersion) c.samples = 0;
    c.occupancyVersion = visibility;

    FramePlan plan;
    plan.inputsChanged = inputsChanged;
    plan.drawGBuffer = !c.gBufferValid;
    if (plan.drawGBuffer) {
        c.gBufferValid = true;
        c.samples = 0;
    }
    plan.gather = !mSettings.progressive || c.samples == 0 ||
                  (mSettings.rotate && c.samples < mSettings.targetSamples);
    if (plan.gather) {
        if (!mSettings.progressive) c.samples = 0;
        plan.restart = c.samples == 0;
        // Progressive sets rotate with the sets summed so far, others with the frame.
        const std::uint32_t set = mSettings.progressive
                ? std::uint32_t(c.samples / std::max(mSettings.samples, 1))
                : mFrameIndex;
        plan.rotation = mSettings.rotate ? cranleyPattersonOffset(set) : glm::vec2(0.0f);
        c.samples += mSettings.samples;
    }
    plan.view = atlasView(in.debugView);
    return plan;
}

void AtlasGi::update(const GiFrameInputs& in, gl::GpuProfiler& profiler) {
    if (mMesh.triangleCount() == 0) return;
    if (mFollowsPose && mPosedGeometry != in.scene.geometryVersion()) {
        mPose.execute({in.scene}, {mGeometry}, profiler);
        mPosedGeometry = in.scene.geometryVersion();
    }
    const OccupancyVolume* occupancy = visibilityOccupancy(in);
    const int bvhRayIterations = visibilityBvh(in);
    const FramePlan plan = planFrame(in, occupancy);
    // The senders' importance by the view follows what the camera sees in this frame: taken
    // for the first gather, when the geometry or the lights changed (the G-buffer is drawn
    // again), and when the camera has moved far enough (scene::viewMovedFarFrom) since. So a
    // renderer that saw the scene move draws the same senders as one that sees it only as it is
    // now. By the surfaces it follows the geometry and the lights alone (where the texels lie
    // and which send), not every G-buffer: without atlas.progressive one is drawn every frame.
    const bool byView = drawsByImportance() && mSettings.importance == ATLAS_IMPORTANCE_VIEW;
    const bool bySurfaces =
            drawsByImportance() && mSettings.importance == ATLAS_IMPORTANCE_SURFACES;
    const bool sampleView = byView && plan.gather &&
            (!mViewSampledFrom || plan.drawGBuffer ||
                    scene::viewMovedFarFrom(*mViewSampledFrom, in.camera,
                            glm::length(in.scene.bounds().size())));
    const bool sampleSurfaces = bySurfaces && plan.gather &&
                                (plan.inputsChanged || !mImportanceReady);
    if (sampleView || sampleSurfaces) mImportanceReady = true;   // computed below, before the draws
    writeUniforms(plan, in);
    // Progressive sums gather until they reach atlas.target_samples; without progression
    // every frame is computed afresh, and only a change of inputs breaks from the last one.
    mConverging = mSettings.progressive ? plan.gather : plan.inputsChanged;

    if (plan.drawGBuffer) {
        mGBuffer.execute({in.scene, mGeometry, in.shadows, in.frameUniforms, mUniforms},
                {mTextures}, profiler);
        if (mSettings.filter) mDilate.drawSurfaceMask({mTextures, mUniforms}, profiler);
    }
    if (sampleView) {
        // The resolve draws the view's depth (its light is the last frame's and is drawn
        // again below).
        mResolve.execute({in.scene, mGeometry, in.frameUniforms, mUniforms, mTextures},
                {in.outputSize}, profiler);
        mSenderSampling.takeViewSamples(mResolve.indirect(), in.frameUniforms, profiler);
        mSenderSampling.computeImportance(mTextures, mUniforms, profiler);
        mViewSampledFrom = in.camera;
        ++mViewSampleTakes;
    }
    if (sampleSurfaces) {
        mSenderSampling.takeSurfaceSamples(in.scene.vertexBuffer(), mUniforms, profiler);
        mSenderSampling.computeImportance(mTextures, mUniforms, profiler);
        ++mSurfaceSampleTakes;
    }
    if (plan.gather) {
        if (plan.restart) mGather.clear();
        for (int bounce = 0; bounce < mBounces; ++bounce) {
            if (bounce > 0) mBounceSenders.execute({mTextures, mUniforms}, profiler);
            if (mSettings.estimator == ATLAS_ESTIMATOR_AREA) {
                // The power table follows the senders' radiance: the G-buffer's direct light,
                // which the further bounces' tables replace every frame, and their importance.
                const bool table =
                        plan.drawGBuffer || mBounces > 1 || sampleView || sampleSurfaces;
                mSenderSampling.execute(
                        {mTextures, mUniforms, mSettings.samples, table, bounce}, profiler);
            }
            mGather.execute({mTextures, mSamples, mUniforms, occupancy, mSenderSampling, bounce,
                                    mSettings.samples, skyDirections(in), bvhRayIterations,
                                    nearRays(in), in.bvhNodes, &mGeometry},
                    {mTextures}, profiler);
            mDilate.execute({mTextures, mUniforms, bounce}, {mTextures}, profiler);
        }
    }
    ++mFrameIndex;

    mResolve.execute({in.scene, mGeometry, in.frameUniforms, mUniforms, mTextures},
            {in.outputSize}, profiler);
    mDebugView = plan.view;
    if (mDebugView >= 0) {
        mDebugViewPass.execute({in.scene, mGeometry, in.frameUniforms, mUniforms, mTextures},
                {in.outputSize}, profiler);
    }
}

GiOutputs AtlasGi::outputs() const {
    GiOutputs out;
    if (mMesh.triangleCount() == 0) return out;
    out.indirect = &mResolve.indirect();
    out.size = mResolve.size();
    out.debugImage = mDebugView >= 0 ? &mDebugViewPass.image() : nullptr;
    out.converging = mConverging;
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
