#include "render/FrameRenderer.h"

#include "gi/atlas/AtlasGi.h"
#include "gi/voxel/VoxelizationManager.h"
#include "gi/vpl/VplGi.h"
#include "gl/Limits.h"
#include "gl/Shared.h"
#include "render/FrameSwitches.h"

#include <glm/gtc/matrix_inverse.hpp>

#include <algorithm>
#include <climits>
#include <cstdio>

namespace gi::render {

bool FrameRenderer::shadowMapsFit(const std::vector<scene::Light>& lights,
        const ShadowSettings& settings, std::string& error) {
    return gl::fitsResourceBudget(std::to_string(lights.size()) + " light(s) at " +
                    ShadowPass::resolutionText(lights, settings) + " (shadow maps)",
            ShadowPass::memoryFor(lights, settings), error);
}

ResourcePlan FrameRenderer::planFor(const Settings& requested) const {
    const scene::Scene& scene = *mSceneDescription;
    const glm::vec3 eye = scene.cameras.empty() ? scene.bounds.center()
                                                : glm::vec3(scene.cameras.front().worldFromCamera[3]);
    return planResources(scene, mAllLights, requested, eye);
}

bool FrameRenderer::init(const scene::Scene& scene, const Settings& settings,
        gl::ShaderLibrary& shaders, std::string& error) {
    const gl::MemoryScope memoryScope(mMemory);
    mShaders = &shaders;
    mSceneDescription = &scene;
    mPosedScene = &scene;
    mAllLights = scene.lights;
    mRequested = settings;
    mPlan = planFor(settings);
    mSettings = applyPlan(settings, mPlan);
    mLights = plannedLights(mAllLights, mPlan);
    if (!shadowMapsFit(mLights, mSettings.shadow, error) ||
            !lineSpaceFits(scene, mSettings, error)) {
        return false;
    }
    mScene = std::make_unique<scene::GpuScene>(scene);
    if (mLights != scene.lights) mScene->setLights(mLights);
    mFrameUniforms = gl::createBuffer(sizeof(shader::FrameUniforms), nullptr,
            GL_DYNAMIC_STORAGE_BIT, "frame/uniforms");
    if (!mShadows.init(shaders, error) || !mForward.init(shaders, error) ||
            !mTemporal.init(shaders, error)) {
        return false;
    }
    mShadows.setLights(mLights, mScene->bounds(), mSettings.shadow);
    return true;
}

bool FrameRenderer::setSettings(const Settings& requested, std::string& error) {
    const gl::MemoryScope memoryScope(mMemory);
    ResourcePlan plan = planFor(requested);
    const Settings settings = applyPlan(requested, plan);
    std::vector<scene::Light> lights = plannedLights(mAllLights, plan);
    const bool lightsChanged = lights != mLights;
    const bool shadowsChanged = !(settings.shadow == mSettings.shadow) || lightsChanged;
    const bool lineSpaceChanged = shadowsChanged || !(settings.lineSpace == mSettings.lineSpace);
    if ((shadowsChanged && !shadowMapsFit(lights, settings.shadow, error)) ||
            (lineSpaceChanged && !lineSpaceFits(*mSceneDescription, settings, error))) {
        return false;
    }
    if (mGi && !mGi->configure(settings, error)) return false;
    mRequested = requested;
    mPlan = std::move(plan);
    mSettings = settings;
    mTemporal.reset();
    if (lightsChanged) {
        mLights = std::move(lights);
        mScene->setLights(mLights);
    }
    if (shadowsChanged) mShadows.setLights(mLights, mScene->bounds(), mSettings.shadow);
    return true;
}

std::optional<OccupancyVolume> FrameRenderer::updateOccupancy(const scene::CameraView& camera,
        gl::GpuProfiler& profiler) {
    Settings occupancySettings = mSettings;
    occupancySettings.voxel.sceneCentred = true;
    occupancySettings.voxel.coverageMaxAxis = true;
    occupancySettings.voxel.projectedAreas = true;
    // The marches read occupied voxels and their coverage, never a face's light, and trace no
    // cones: the occupancy keeps no directional copy (voxel.anisotropic) and leaves the cones'
    // light read (voxel.light_read, which asks for that copy) to voxel GI.
    occupancySettings.voxel.anisotropic = false;
    occupancySettings.voxel.lightRead = LIGHT_READ_CONE;
    // The occupancy holds the whole scene in its finest level, whatever the plan's placement.
    if (mSettings.plan == PLAN_ADAPTIVE) occupancySettings.voxel.extent = 0.0f;
    // Its resolution is voxel.occupancy_resolution, else the requested voxel.resolution: the
    // one level the adaptive plan may give the cone trace (ResourcePlan.cpp) is the trace's,
    // and the visibility marches keep the cost they had.
    occupancySettings.voxel.resolution = mSettings.voxel.occupancyResolution > 0
            ? mSettings.voxel.occupancyResolution
            : mRequested.voxel.resolution;
    occupancySettings.voxel.multiplier = mRequested.voxel.multiplier;
    // One sample a pixel: the samples find slivers of surfaces in neighbouring voxels, which
    // an unlit occupancy voxel turns into a whole voxel's coverage; the walls the marches
    // cross grew thicker (the open-front box's converged atlas kept 0.946 of the energy
    // instead of 0.964, accuracy-analysis.md). Only injection needs every voxel a light lights.
    occupancySettings.voxel.msaa = 1;
    // The scene is all in the finest level, and the voxelization raster spans the coarsest, so
    // each level more halves the raster samples per finest voxel and leaves holes in thin
    // walls that the visibility marches pass through. The marches of the atlas and the VPLs
    // walk only the finest level; shadow cones widen towards an area light, and the coarser
    // levels (the same scene at 2x and 4x the voxel) are their pre-filtered footprints.
    occupancySettings.voxel.levels = voxelShadows() ? kShadowConeLevels : 1;
    std::string error;
    const gl::MemoryScope memoryScope(mOccupancyMemory);
    if (!mOccupancy) {
        mOccupancy = std::make_unique<voxel::VoxelizationManager>();
        if (!mOccupancy->init(*mShaders, *mSceneDescription, error)) {
            std::fprintf(stderr, "voxel occupancy: %s\n", error.c_str());
            mOccupancy.reset();
            return std::nullopt;
        }
    }
    if (!mOccupancy->configure(occupancySettings, error)) {
        std::fprintf(stderr, "voxel occupancy: %s\n", error.c_str());
        return std::nullopt;
    }
    mOccupancy->updateOccupancy({*mScene, mLights, mShadows, mFrameUniforms, camera, mRenderSize},
            profiler);
    return mOccupancy->occupancy();
}

bool FrameRenderer::setMode(GiMode mode, std::string& error) {
    if (mode == mMode && (mGi || mode == GiMode::Direct)) return true;
    const gl::MemoryScope memoryScope(mMemory);
    std::unique_ptr<GiTechnique> technique;
    if (mode == GiMode::Voxel) {
        technique = std::make_unique<voxel::VoxelizationManager>();
    } else if (mode == GiMode::Atlas) {
        technique = std::make_unique<atlas::AtlasGi>();
    } else if (mode == GiMode::Vpl) {
        technique = std::make_unique<vpl::VplGi>();
    } else if (mode != GiMode::Direct) {
        error = "the reference renderer is not a GPU mode";
        return false;
    }
    if (technique && (!technique->init(*mShaders, *mSceneDescription, error) ||
                             !technique->configure(mSettings, error))) {
        return false;
    }
    // Only the active technique keeps GPU memory.
    mGi = std::move(technique);
    mMode = mode;
    mTemporal.reset();
    return true;
}

void FrameRenderer::setLights(const std::vector<scene::Light>& lights) {
    const gl::MemoryScope memoryScope(mMemory);
    mAllLights = lights;
    mPlan = planFor(mRequested);
    mSettings = applyPlan(mRequested, mPlan);
    mLights = plannedLights(mAllLights, mPlan);
    mTemporal.reset();
    mScene->setLights(mLights);
    mShadows.setLights(mLights, mScene->bounds(), mSettings.shadow);
}

void FrameRenderer::setPose(const scene::Scene& scene) {
    const gl::MemoryScope memoryScope(mMemory);
    mScene->updateDynamic(scene);
    mPosedScene = &scene;
    if (mScene->geometryVersion() != mShadowGeometry) {
        mShadowGeometry = mScene->geometryVersion();
        mShadows.invalidate();
    }
}

bool FrameRenderer::voxelShadows() const {
    return mSettings.shadow.enabled && mSettings.shadow.method == SHADOW_METHOD_VOXEL;
}

void FrameRenderer::updateShadowRays(gl::GpuProfiler& profiler) {
    if (!mSettings.shadow.enabled) return;
    const scene::Scene& scene = *mPosedScene;
    std::string error;
    if (mSettings.shadow.method == SHADOW_METHOD_BVH &&
            !mBvhShadows.update(scene, mScene->geometryVersion(), profiler, error)) {
        std::fprintf(stderr, "shadow.method=bvh: %s\n", error.c_str());
    }
    if (mSettings.shadow.method == SHADOW_METHOD_LINESPACE &&
            !mLineSpace.update(*mShaders, scene, mScene->geometryVersion(), mSettings.lineSpace,
                    profiler, error)) {
        std::fprintf(stderr, "shadow.method=linespace: %s\n", error.c_str());
    }
}

int FrameRenderer::updateGiBvh(gl::GpuProfiler& profiler) {
    // The atlas' near field walks it whatever tests the visibility of its other senders.
    const bool atlasNearField = mSettings.atlas.estimator == ATLAS_ESTIMATOR_AREA &&
                                mSettings.atlas.nearRays > 0;
    const bool wanted =
            (mMode == GiMode::Atlas &&
                    (mSettings.atlas.visibility == ATLAS_VISIBILITY_BVH || atlasNearField)) ||
            (mMode == GiMode::Vpl && mSettings.vpl.visibility == VPL_VISIBILITY_BVH);
    if (!wanted) return 0;
    std::string error;
    if (!mBvhShadows.update(*mPosedScene, mScene->geometryVersion(), profiler, error)) {
        std::fprintf(stderr, "%s: %s\n",
                mMode == GiMode::Vpl                                   ? "vpl.visibility=bvh"
                : mSettings.atlas.visibility == ATLAS_VISIBILITY_BVH ? "atlas.visibility=bvh"
                                                                       : "atlas.near_rays",
                error.c_str());
        return 0;
    }
    mBvhShadows.bind();
    const reference::GpuBvh& bvh = mBvhShadows.bvh();
    const std::size_t iterations = bvh.nodeCount() + bvh.triangleCount();
    return int(std::min<std::size_t>(std::max<std::size_t>(iterations, 1), std::size_t(INT_MAX)));
}

void FrameRenderer::writeFrameUniforms(const scene::CameraView& camera, OutputComponent output) {
    shader::FrameUniforms frame{};
    frame.viewProjection = camera.viewProjection();
    frame.inverseViewProjection = glm::inverse(frame.viewProjection);
    frame.view = camera.view;
    frame.cameraPosition = glm::vec4(camera.eye, 1.0f);
    const FrameSwitches switches = FrameSwitches::of(mSettings);
    frame.shading = glm::vec4(mSettings.specular, mSettings.shininess,
            float(switches.shadingModel), switches.shadows ? 1.0f : 0.0f);
    const int outputKind = output == OutputComponent::Final    ? OUTPUT_FINAL
                           : output == OutputComponent::Direct ? OUTPUT_DIRECT
                                                               : OUTPUT_INDIRECT;
    frame.screen = glm::vec4(glm::vec2(mRenderSize), 0.0f, 0.0f);
    frame.counts = glm::ivec4(mScene->lightCount(), outputKind, 0, switches.upsample);
    frame.sky = glm::vec4(scene::skyRadiance(mLights) * mScene->exposure(), 0.0f);
    const float offset = mScene->bounds().rayOffset();
    frame.shadowing = glm::vec4(float(switches.shadowMethod), float(mSettings.shadow.rays), offset, 0.0f);
    glNamedBufferSubData(mFrameUniforms.id(), 0, sizeof frame, &frame);
}

void FrameRenderer::render(const scene::CameraView& camera, glm::ivec2 outputSize,
        OutputComponent output, gl::GpuProfiler& profiler) {
    const gl::MemoryScope memoryScope(mMemory);
    profiler.newFrame();
    mTarget.resize(outputSize * mSettings.supersample);
    mRenderSize = mTarget.size();
    mLastOutput = output;
    writeFrameUniforms(camera, output);

    // Without GI the shadow maps serve only shadow.method=shadowmap; GI injects with them.
    if (mGi || mSettings.shadow.method == SHADOW_METHOD_SHADOWMAP) {
        mShadows.execute({*mScene}, profiler);
    }
    const bool needsOccupancy = voxelShadows() ||
            (mMode == GiMode::Atlas && mSettings.atlas.visibility == ATLAS_VISIBILITY_VOXEL) ||
            (mMode == GiMode::Vpl && (mSettings.vpl.visibility == VPL_VISIBILITY_CASCADE ||
                                             mSettings.vpl.bounces > 1));
    if (!needsOccupancy) mOccupancy.reset();
    const std::optional<OccupancyVolume> occupancy =
            needsOccupancy ? updateOccupancy(camera, profiler) : std::nullopt;
    const int bvhRayIterations = updateGiBvh(profiler);
    const int bvhNodes = bvhRayIterations > 0 ? int(std::min<std::size_t>(
                                                        mBvhShadows.bvh().nodeCount(), INT_MAX))
                                              : 0;
    GiOutputs gi;
    if (mGi) {
        const DebugView debugView = outputAvailable(output, mMode)
                                            ? outputEntry(output).debugView
                                            : DebugView::None;
        mGi->update({*mScene, mLights, mShadows, mFrameUniforms, camera, mRenderSize, debugView,
                            occupancy ? &*occupancy : nullptr, bvhRayIterations, bvhNodes},
                profiler);
        gi = mGi->outputs();
    }
    if (gi.indirect && !gi.debugImage && mSettings.temporal.filter) {
        // A technique still accumulating is its own temporal filter: the history starts
        // from the light it settles on.
        if (gi.converging) mTemporal.reset();
        const bool geometryMoved = mScene->geometryVersion() != mTemporalGeometry;
        mTemporalGeometry = mScene->geometryVersion();
        gi.indirect = &mTemporal.execute({*gi.indirect, gi.size, mFrameUniforms, camera,
                                                  mSettings.temporal, gi.resampled, geometryMoved},
                profiler);
    } else {
        mTemporal.reset();
    }
    mLastIndirect = mGi ? IndirectImages{mGi->outputs().indirect, gi.indirect, gi.size}
                        : IndirectImages{};
    if (gi.debugImage) {
        glCopyImageSubData(gi.debugImage->id(), GL_TEXTURE_2D, 0, 0, 0, 0, mTarget.color().id(),
                GL_TEXTURE_2D, 0, 0, 0, 0, mRenderSize.x, mRenderSize.y, 1);
        return;
    }
    updateShadowRays(profiler);
    mBvhShadows.bind();
    mLineSpace.bind();
    if (voxelShadows() && occupancy) {
        // The technique may have bound its own cascade at the same slots.
        glBindTextureUnit(BIND_TEX_VOXEL_ALBEDO, occupancy->coverage.id());
        glBindBufferBase(GL_UNIFORM_BUFFER, BIND_UBO_VOXEL, occupancy->voxelUniforms.id());
    }
    FrameSwitches switches = FrameSwitches::of(mSettings);
    switches.shadowMaps = mShadows.mapKinds();
    switches.materialTextures = mScene->textureKinds();
    switches.lightKinds = mScene->lightKinds();
    const ForwardPass::Inputs forward{*mScene, mShadows, mFrameUniforms, gi.indirect, gi.size,
            mSettings.depthPrepass, gi.indirectSpecular, switches};
    if (mSettings.msaa <= 1) {
        mForward.execute(forward, {mTarget}, profiler);
        return;
    }
    // Each surface a pixel's samples cover is shaded once, at the pixel's centre; the resolve
    // averages the samples, so a pixel on a silhouette holds both surfaces by the area each
    // covers, as the path tracer's pixel does (docs/conventions.md).
    mSamples.resize(mRenderSize,
            gl::supportedSamples({GL_RGBA32F, GL_DEPTH_COMPONENT32F}, mSettings.msaa));
    mForward.execute(forward, {mSamples}, profiler);
    gl::GpuScope scope(profiler, "render/resolve");
    glBlitNamedFramebuffer(mSamples.framebuffer().id(), mTarget.framebuffer().id(), 0, 0,
            mRenderSize.x, mRenderSize.y, 0, 0, mRenderSize.x, mRenderSize.y,
            GL_COLOR_BUFFER_BIT, GL_NEAREST);
}

float FrameRenderer::radianceScale() const {
    return isRadiometric(mLastOutput) ? 1.0f / mScene->exposure() : 1.0f;
}

std::vector<float> FrameRenderer::readTarget() const {
    std::vector<float> rgba(std::size_t(mRenderSize.x) * std::size_t(mRenderSize.y) * 4);
    glGetTextureImage(mTarget.color().id(), 0, GL_RGBA, GL_FLOAT,
            GLsizei(rgba.size() * sizeof(float)), rgba.data());
    return rgba;
}

core::Image FrameRenderer::readback() const {
    core::Image full(mRenderSize.x, mRenderSize.y);
    const std::vector<float> rgba = readTarget();
    // GL rows run bottom to top; images run top to bottom.
    const float scale = radianceScale();
    for (int y = 0; y < mRenderSize.y; ++y) {
        const float* row = rgba.data() + std::size_t(mRenderSize.y - 1 - y) * std::size_t(mRenderSize.x) * 4;
        for (int x = 0; x < mRenderSize.x; ++x) {
            full.set(x, y, glm::vec3(row[x * 4], row[x * 4 + 1], row[x * 4 + 2]) * scale);
        }
    }
    return boxDownsample(full, mSettings.supersample);
}

std::vector<float> FrameRenderer::readbackCoverage() const {
    core::Image full(mRenderSize.x, mRenderSize.y);
    const std::vector<float> rgba = readTarget();
    for (int y = 0; y < mRenderSize.y; ++y) {
        const float* row = rgba.data() + std::size_t(mRenderSize.y - 1 - y) * std::size_t(mRenderSize.x) * 4;
        for (int x = 0; x < mRenderSize.x; ++x) full.set(x, y, glm::vec3(row[x * 4 + 3]));
    }
    const core::Image averaged = boxDownsample(full, mSettings.supersample);
    std::vector<float> coverage(std::size_t(averaged.width) * std::size_t(averaged.height));
    for (std::size_t i = 0; i < coverage.size(); ++i) coverage[i] = averaged.rgb[i * 3];
    return coverage;
}

ShadowMethodReport FrameRenderer::shadowReport() const {
    ShadowMethodReport report = plannedShadowMethod(*mPosedScene, mLights, mSettings);
    report.bound = false;
    auto bytesUnder = [this](const std::string& prefix) {
        std::size_t bytes = 0;
        for (const gl::MemoryItem& item : memory()) {
            if (item.name.rfind(prefix, 0) == 0) bytes += item.bytes;
        }
        return bytes;
    };
    const int method = mSettings.shadow.method;
    if (!mSettings.shadow.enabled) return report;
    if (method == SHADOW_METHOD_SHADOWMAP) {
        report.bytes = bytesUnder("render/shadow/");
    } else if (method == SHADOW_METHOD_VOXEL) {
        report.bytes = bytesUnder("occupancy/");
    } else if (method == SHADOW_METHOD_BVH) {
        const reference::GpuBvh& bvh = mBvhShadows.bvh();
        report.structure = "BVH over " + std::to_string(bvh.triangleCount()) + " triangles, " +
                std::to_string(bvh.nodeCount()) + " nodes";
        report.buildMs = bvh.buildSeconds * 1000.0;
        report.bytes = bvh.bytes();
    } else {
        const LineSpaceStats& ls = mLineSpace.stats();
        report.structure = "LS(" + std::to_string(ls.n) + "," + std::to_string(ls.depth) + ") over " +
                std::to_string(ls.triangles) + " triangles, " + std::to_string(ls.nodes) + " nodes";
        report.buildMs = ls.buildMilliseconds;
        report.bytes = ls.bytes;
    }
    return report;
}

std::optional<vpl::VplReport> FrameRenderer::vplReport() const {
    if (mMode != GiMode::Vpl || !mGi) return std::nullopt;
    return static_cast<const vpl::VplGi&>(*mGi).report();
}

std::vector<gl::MemoryItem> FrameRenderer::memory() const {
    std::vector<gl::MemoryItem> items = mMemory.report();
    for (gl::MemoryItem& item : mOccupancyMemory.report()) items.push_back(std::move(item));
    return items;
}

} // namespace gi::render
