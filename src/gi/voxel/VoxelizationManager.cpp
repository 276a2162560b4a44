#include "gi/voxel/VoxelizationManager.h"

#include "gi/voxel/ConeSet.h"
#include "gi/voxel/RingDither.h"
#include "gl/Limits.h"

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace gi::voxel {
namespace {

bool isPowerOfTwo(int n) { return n > 0 && (n & (n - 1)) == 0; }

// The filter's radius in trace texels (0: no filter). voxel.filter is in texels of the
// half-resolution trace; other trace scales scale it, so the filter smooths the same part of
// the image and a finer trace only adds detail.
int filterTexels(const VoxelSettings& settings) {
    if (settings.filterRadius <= 0) return 0;
    const float texels = std::round(float(settings.filterRadius) * settings.traceScale / 0.5f);
    return std::clamp(int(texels), 1, VOXEL_FILTER_MAX_RADIUS);
}

} // namespace

bool VoxelizationManager::init(gl::ShaderLibrary& shaders, const scene::Scene& scene,
        std::string& error) {
    mSceneBounds = scene.bounds;
    mUniforms = gl::createBuffer(sizeof(shader::VoxelUniforms), nullptr, GL_DYNAMIC_STORAGE_BIT,
            "voxel/uniforms");
    return mVoxelize.init(shaders, error) && mInject.init(shaders, error) &&
           mPropagate.init(shaders, error) && mBounce.init(shaders, error) &&
           mDirectional.init(shaders, error) &&
           mEmptyDistance.init(shaders, error) && mEdgeFaces.init(shaders, error) &&
           mPyramid.init(shaders, error) &&
           mTrace.init(shaders, error) &&
           mReuse.init(shaders, error) && mFilter.init(shaders, error) &&
           mDebugView.init(shaders, error);
}

bool VoxelizationManager::configure(const Settings& settings, std::string& error) {
    const VoxelSettings& s = settings.voxel;
    if (!isPowerOfTwo(s.resolution) || s.resolution < 4) {
        error = "voxel.resolution " + std::to_string(s.resolution) +
                " must be a power of two (4..256): nested levels share 2x2x2 voxel blocks";
        return false;
    }
    GLint max3D = 0;
    glGetIntegerv(GL_MAX_3D_TEXTURE_SIZE, &max3D);
    if (s.resolution * s.levels > max3D) {
        error = "voxel.resolution x voxel.cascades = " + std::to_string(s.resolution * s.levels) +
                " exceeds GL_MAX_3D_TEXTURE_SIZE " + std::to_string(max3D);
        return false;
    }
    if (s.anisotropic && s.resolution * VOXEL_FACES > max3D) {
        error = "voxel.anisotropic: 6 x voxel.resolution = " +
                std::to_string(s.resolution * VOXEL_FACES) + " exceeds GL_MAX_3D_TEXTURE_SIZE " +
                std::to_string(max3D);
        return false;
    }
    if (s.resolution / 2 * VOXEL_FACES > max3D) {
        error = "voxel.resolution: the light pyramid's 6 faces of voxel.resolution / 2 = " +
                std::to_string(s.resolution / 2 * VOXEL_FACES) +
                " texels exceed GL_MAX_3D_TEXTURE_SIZE " + std::to_string(max3D);
        return false;
    }
    GLint maxSamples = 0;
    glGetIntegerv(GL_MAX_FRAMEBUFFER_SAMPLES, &maxSamples);
    if (s.msaa > std::max(maxSamples, 1)) {
        error = "voxel.msaa: " + std::to_string(s.msaa) +
                " samples exceed GL_MAX_FRAMEBUFFER_SAMPLES " + std::to_string(maxSamples);
        return false;
    }
    GLint maxViewport[2] = {0, 0};
    glGetIntegerv(GL_MAX_VIEWPORT_DIMS, maxViewport);
    if (s.resolution * s.multiplier > std::min(maxViewport[0], maxViewport[1])) {
        error = "voxel.resolution x voxel.multiplier = " + std::to_string(s.resolution * s.multiplier) +
                " exceeds the largest viewport " + std::to_string(maxViewport[0]);
        return false;
    }
    // 44 bytes per voxel, 92 anisotropic, 8 more for further bounces (VoxelTextures.h);
    // refuse before allocating rather than let the driver fail (or swap) halfway through a
    // frame.
    const double bytesPerVoxel =
            (s.anisotropic ? 92.0 : 44.0) + (settings.giBounces > 1 ? 8.0 : 0.0);
    const double bytes = bytesPerVoxel * std::pow(double(s.resolution), 3.0) * double(s.levels);
    if (!gl::fitsResourceBudget("voxel.resolution " + std::to_string(s.resolution) +
                    " with voxel.cascades " + std::to_string(s.levels) + " (voxel textures)",
                bytes, error)) {
        return false;
    }
    if (settings.giBounces > 1 && s.anisotropic) {
        error = "gi.bounces " + std::to_string(settings.giBounces) +
                " needs isotropic voxels (voxel.anisotropic=0): the directional voxels keep no "
                "irradiance a further bounce could add to";
        return false;
    }
    // Which pixels a frame traces (voxel.trace_reuse) leaves the voxels as they are: switching
    // it only starts the reuse over.
    VoxelSettings sameVoxels = s;
    sameVoxels.traceReuse = mSettings.traceReuse;
    if (!mConfigured || !(sameVoxels == mSettings) || settings.giBounces != mBounces ||
            settings.glossyMaterials() != mGlossyMaterials) {
        mContent = Content::None;
        mStaticCacheValid = false;
    }
    if (mConfigured && s.traceReuse != mSettings.traceReuse) mReuse.dropHistory();
    const bool reallocate = !mConfigured || s.resolution != mSettings.resolution ||
                            s.levels != mSettings.levels || s.anisotropic != mSettings.anisotropic ||
                            s.projectedAreas != mSettings.projectedAreas ||
                            (settings.giBounces > 1) != (mBounces > 1);
    const bool replace = reallocate || s.extent != mSettings.extent ||
                         s.sceneCentred != mSettings.sceneCentred ||
                         s.clampCentre != mSettings.clampCentre;
    mSettings = s;
    mBounces = settings.giBounces;
    mGlossyMaterials = settings.glossyMaterials();
    mConfigured = true;
    if (reallocate) {
        mTextures.allocate(s.resolution, s.levels, s.anisotropic, mBounces > 1, s.projectedAreas);
    }
    if (replace) mFinestExtent = s.extent;
    return true;
}

void VoxelizationManager::writeUniforms() {
    shader::VoxelUniforms u{};
    for (int level = 0; level < CascadeVolume::kMaxLevels; ++level) {
        const int l = std::min(level, mVolume.levels() - 1);
        u.levelOrigin[level] = glm::vec4(mVolume.origin(l), mVolume.voxelSize(l));
    }
    const bool surfaceRead = mSettings.lightRead == LIGHT_READ_SURFACE;
    const int kind = mSettings.anisotropic
            ? (surfaceRead ? VOXEL_KIND_ANISOTROPIC_SURFACE_READ : VOXEL_KIND_ANISOTROPIC)
            : (surfaceRead ? VOXEL_KIND_ISOTROPIC_SURFACE_READ : VOXEL_KIND_ISOTROPIC);
    u.grid = glm::ivec4(mVolume.resolution(), mVolume.levels(), kind, mSettings.pyramidMips);
    const ConeSet cones = coneSet(mSettings.cones, mSettings.coneAngle);
    const float halfAngle = glm::radians(cones.apertureDegrees) * 0.5f;
    const float maxDistance = mSettings.maxDistance > 0.0f
            ? mSettings.maxDistance
            : mVolume.extent(mVolume.levels() - 1) * std::sqrt(3.0f);
    u.trace = glm::vec4(std::tan(halfAngle), maxDistance, mSettings.stepFactor,
            mSettings.falloff ? 1.0f : 0.0f);
    const int filterRadius = filterTexels(mSettings);
    const float dither = mSettings.jitter ? float(ringDither(filterRadius).code()) : 0.0f;
    u.smoothing = glm::vec4(float(filterRadius), dither, std::log2(mSettings.footprint),
            mSettings.coneOffset);
    const int classes = conePixelClasses(mSettings.cones, mSettings.coneInterleave, filterRadius);
    u.cones = glm::vec4(cones.centralWeight, float(classes),
            mSettings.jitter && mSettings.jitterElevation ? 1.0f : 0.0f, mSettings.walkStart);
    for (std::size_t k = 0; k < cones.rings.size(); ++k) {
        const ConeRing& ring = cones.rings[k];
        const float sine = std::sin(ring.elevation);
        u.coneRings[k] = glm::vec4(float(ring.count), sine * sine, ring.riseReach, ring.weight);
    }
    // One raster over the coarsest level, or one per level over its own extent
    // (voxelize.geom); either way a pixel is 1/multiplier of the rasterized level's voxel.
    const float rasterPixel = 1.0f / float(mSettings.multiplier);
    u.raster = glm::vec4(mSettings.rasterPerLevel ? 1.0f : 0.0f, rasterPixel * rasterPixel,
            mSettings.projectedAreas ? 1.0f : 0.0f, 0.0f);
    u.modes = glm::vec4(mSettings.injectFragmentMean ? INJECT_FRAGMENT : INJECT_AREA,
            mGlossyMaterials ? 1.0f : 0.0f, mSettings.coverageMaxAxis ? 1.0f : 0.0f,
            mSettings.coarsePlanes ? 1.0f : 0.0f);
    glNamedBufferSubData(mUniforms.id(), 0, sizeof u, &u);
}

void VoxelizationManager::updateOccupancy(const GiFrameInputs& in, gl::GpuProfiler& profiler) {
    place(in);
    mShowDebug = false;
    if (contentReusable(in, Content::Occupancy)) {
        ++mReusedFrames;
        return;
    }
    voxelize(in, profiler);
    mPropagate.execute({mUniforms}, {mTextures}, profiler);
    if (mSettings.projectedAreas) mEdgeFaces.execute({mUniforms}, {mTextures}, profiler);
    rememberContent(in, Content::Occupancy);
}

void VoxelizationManager::place(const GiFrameInputs& in) {
    if (mFinestExtent <= 0.0f) {
        mFinestExtent = mSettings.sceneCentred
                ? CascadeVolume::finestExtentCovering(mSceneBounds)
                : CascadeVolume::finestExtentFor(mSceneBounds, in.camera.eye, mSettings.levels);
    }
    bool moved = false;
    if (mVolume.resolution() != mSettings.resolution || mVolume.levels() != mSettings.levels ||
            mVolume.extent(0) != mFinestExtent) {
        mVolume = CascadeVolume(mSettings.resolution, mSettings.levels, mFinestExtent);
        moved = true;
    }
    glm::vec3 centre = in.camera.eye;
    if (!mSceneBounds.empty()) {
        if (mSettings.sceneCentred) centre = mSceneBounds.center();
        else if (mSettings.clampCentre) centre = glm::clamp(centre, mSceneBounds.min, mSceneBounds.max);
    }
    moved |= mVolume.placeAround(centre);
    mPlacementMoved = moved;
    if (moved || mContentScene != &in.scene) {
        mContent = Content::None;
        mStaticCacheValid = false;
    }
    writeUniforms();
}

bool VoxelizationManager::contentReusable(const GiFrameInputs& in, Content content) const {
    // Animated geometry bumps the version whenever it is posed (a paused animation does not);
    // lights change what is injected (and the pre-exposure every radiometric value carries).
    return mSettings.cache && mContent == content && mContentScene == &in.scene &&
           mContentGeometry == in.scene.geometryVersion() &&
           (content == Content::Occupancy || mContentLights == in.lights);
}

void VoxelizationManager::rememberContent(const GiFrameInputs& in, Content content) {
    mContent = content;
    mContentScene = &in.scene;
    mContentGeometry = in.scene.geometryVersion();
    mContentLights = in.lights;
    ++mContentVersion;
}

void VoxelizationManager::voxelize(const GiFrameInputs& in, gl::GpuProfiler& profiler) {
    using DrawSet = scene::GpuScene::DrawSet;
    const int rasterSize = mSettings.resolution * mSettings.multiplier;
    const int samples = std::max(mSettings.msaa, 1);   // 0 (the plan's) resolves before here
    const bool split = mSettings.cache && in.scene.hasDynamicGeometry();
    if (!split) mStaticCache.release();
    if (split && mStaticCacheValid) {
        gl::GpuScope scope(profiler, "voxel/restore-static");
        mStaticCacheValid = mStaticCache.restore(mTextures);
    }
    if (!split || !mStaticCacheValid) {
        {
            gl::GpuScope scope(profiler, "voxel/clear");
            mTextures.clear();
        }
        mVoxelize.execute({in.scene, mUniforms, rasterSize, samples,
                                   split ? DrawSet::Static : DrawSet::All},
                {mTextures}, profiler);
        if (split) {
            gl::GpuScope scope(profiler, "voxel/save-static");
            mStaticCache.save(mTextures);
            mStaticCacheValid = true;
        }
    }
    if (split) {
        mVoxelize.execute({in.scene, mUniforms, rasterSize, samples, DrawSet::Dynamic}, {mTextures},
                profiler);
    }
}

void VoxelizationManager::update(const GiFrameInputs& in, gl::GpuProfiler& profiler) {
    place(in);
    if (contentReusable(in, Content::Lit)) {
        ++mReusedFrames;
    } else {
        voxelize(in, profiler);
        injectAndPropagate(in, profiler);
        rememberContent(in, Content::Lit);
    }
    trace(in, profiler);
}

void VoxelizationManager::injectAndPropagate(const GiFrameInputs& in, gl::GpuProfiler& profiler) {
    const int injectResolution = mSettings.injectResolution > 0 ? mSettings.injectResolution
                                                                : mSettings.resolution;
    const std::vector<LightView> views =
            injectionViews(in.lights, mVolume, mSceneBounds, injectResolution);
    const double fluxScale = fluxSumScale(in.lights, views, injectResolution,
            mVolume.voxelSize(0), in.scene.exposure());
    mInject.execute({in.scene, views, mUniforms, injectResolution, mSettings.injectFragmentMean,
                            fluxScale},
            {mTextures}, profiler);
    mPropagate.execute({mUniforms}, {mTextures}, profiler);
    if (mTextures.anisotropic) mDirectional.execute({mUniforms, mTextures}, {mTextures}, profiler);
    mEmptyDistance.execute({mUniforms}, {mTextures}, profiler);
    mPyramid.execute({mUniforms, mTextures}, {mTextures}, profiler);
    for (int bounce = 2; bounce <= mBounces; ++bounce) {
        mBounce.execute({mUniforms, in.frameUniforms, bounce == 2}, {mTextures}, profiler);
        mPropagate.execute({mUniforms}, {mTextures}, profiler);
        // Propagation rewrote the coarsest level's centre, distances included, where there
        // is more than one level; the occupancy itself is unchanged.
        if (mTextures.levels > 1) mEmptyDistance.execute({mUniforms}, {mTextures}, profiler);
        mPyramid.execute({mUniforms, mTextures}, {mTextures}, profiler);
    }
}

void VoxelizationManager::trace(const GiFrameInputs& in, gl::GpuProfiler& profiler) {
    glm::ivec2 traceSize = glm::max(
            glm::ivec2(glm::round(glm::vec2(in.outputSize) * mSettings.traceScale)), glm::ivec2(1));
    const ConeTracePass::Inputs traceInputs{in.scene, in.frameUniforms, mUniforms, mTextures,
            mGlossyMaterials};
    if (mSettings.traceReuse) {
        traceSize = (traceSize + 1) / 2 * 2;
        // A frame whose voxels were lit anew traces every pixel, so a changed scene never
        // shows light from before the change; while the light stands still, a quarter.
        // The specular cone's light depends on the view, which reprojection cannot carry: a
        // frame with it traces every pixel.
        const bool reuse = !mGlossyMaterials && mReuse.hasHistory() &&
                           mReuse.size() == traceSize && mTracedContent == mContentVersion;
        // Diagonal neighbours first: two frames cover the blocks evenly.
        constexpr glm::ivec2 kPhases[4] = {{0, 0}, {1, 1}, {1, 0}, {0, 1}};
        const glm::ivec2 phase = reuse ? kPhases[mReusePhase++ % 4] : glm::ivec2(0);
        const int stride = reuse ? 2 : 1;
        mTrace.execute(traceInputs, {traceSize, {stride, phase}}, profiler);
        mReuse.execute({in.scene, in.frameUniforms, in.camera, mTrace.indirect(), stride, phase},
                {traceSize}, profiler);
        mTracedContent = mContentVersion;
        mQuarterTraced = reuse;
    } else {
        mTrace.execute(traceInputs, {traceSize}, profiler);
        mQuarterTraced = false;
    }
    const gl::Texture& traced = mSettings.traceReuse ? mReuse.result() : mTrace.indirect();
    if (mSettings.filterRadius > 0) {
        mFilter.execute({traced, mUniforms, filterTexels(mSettings)}, {traceSize}, profiler);
    }

    mShowDebug = in.debugView != DebugView::None;
    if (mShowDebug) {
        using View = VoxelDebugViewPass::View;
        const View view = in.debugView == DebugView::VoxelAlbedo       ? View::Albedo
                          : in.debugView == DebugView::VoxelIrradiance ? View::Irradiance
                                                                       : View::Normal;
        const int level = std::min(mSettings.debugLevel, mVolume.levels() - 1);
        mDebugView.execute({in.frameUniforms, mUniforms, mTextures, level, view},
                {in.outputSize}, profiler);
    }
}

GiOutputs VoxelizationManager::outputs() const {
    GiOutputs out;
    const gl::Texture& traced = mSettings.traceReuse ? mReuse.result() : mTrace.indirect();
    out.indirect = mSettings.filterRadius > 0 ? &mFilter.result() : &traced;
    out.size = mSettings.traceReuse ? mReuse.size() : mTrace.size();
    out.indirectSpecular = mGlossyMaterials ? &mTrace.specular() : nullptr;
    out.debugImage = mShowDebug ? &mDebugView.image() : nullptr;
    out.resampled = mPlacementMoved;
    return out;
}

} // namespace gi::voxel

namespace gi::voxel {

float VoxelizationManager::gatherReach() const {
    return mVolume.extent(mVolume.levels() - 1) * std::sqrt(3.0f);
}

std::string VoxelizationManager::status() const {
    char line[160];
    std::snprintf(line, sizeof line, "voxels %d^3 x %d level%s, finest %.3g m, coarsest %.3g m, trace %dx%d",
            mVolume.resolution(), mVolume.levels(), mVolume.levels() == 1 ? "" : "s",
            double(mVolume.voxelSize(0)),
            double(mVolume.voxelSize(mVolume.levels() - 1)), outputs().size.x, outputs().size.y);
    return std::string(line) + (mQuarterTraced ? ", a quarter traced" : "");
}

} // namespace gi::voxel
