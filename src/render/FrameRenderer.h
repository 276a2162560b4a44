// Frame orchestration: owns the GPU scene, the per-view uniforms, the render targets and the
// passes, and runs them in order for one view. The same object serves `voxatlas render`
// (read back to an Image), the viewer (presented to the window) and the tests.
#pragma once

#include "gl/GpuProfiler.h"
#include "gl/MemoryRegistry.h"
#include "gl/RenderTarget.h"
#include "gl/ShaderLibrary.h"
#include "scene/CameraView.h"
#include "render/BvhShadows.h"
#include "render/LineSpaceShadows.h"
#include "render/ForwardPass.h"
#include "render/OutputCatalog.h"
#include "render/ResourcePlan.h"
#include "scene/GpuScene.h"
#include "render/ShadowMethodReport.h"
#include "render/ShadowPass.h"
#include "render/TemporalFilter.h"
#include "gi/GiTechnique.h"
#include "gi/voxel/VoxelizationManager.h"
#include "gi/vpl/VplReport.h"
#include "core/Image.h"
#include "core/Settings.h"
#include "scene/Scene.h"

#include <memory>
#include <optional>
#include <string>

namespace gi::render {

class FrameRenderer {
public:
    // Uploads the scene and builds every program; false with one message on failure.
    bool init(const scene::Scene& scene, const Settings& settings, gl::ShaderLibrary& shaders,
            std::string& error);

    // False with a message when the lights' shadow maps at `settings` would exceed the resource
    // budget (gl/Limits.h): 64 point lights at shadow.resolution 1024 take 1.5 GiB. init() and
    // setSettings() check it too; callers check first to tell bad input from a failure.
    [[nodiscard]] static bool shadowMapsFit(const std::vector<scene::Light>& lights,
            const ShadowSettings& settings, std::string& error);

    // Applies settings; false with a message if the active technique cannot honour them.
    // With render.plan=adaptive the GI sizes come from the scene (render/ResourcePlan.h).
    bool setSettings(const Settings& settings, std::string& error);
    // The resource plan behind the current settings, and the settings it produced.
    const ResourcePlan& plan() const { return mPlan; }
    const Settings& effectiveSettings() const { return mSettings; }
    // Switches the GI technique (Direct = none). Reference is not a GPU mode.
    bool setMode(GiMode mode, std::string& error);
    GiMode mode() const { return mMode; }
    void setLights(const std::vector<scene::Light>& lights);
    // Uploads the current pose of `scene`'s animated instances (scene/Animation.h). Shadow
    // maps, voxel GI and the atlas follow them (the atlas keeps its charts and moves their
    // vertices). `scene` must live until the next render.
    void setPose(const scene::Scene& scene);

    // Renders one frame of `camera` at outputSize x render.supersample.
    void render(const scene::CameraView& camera, glm::ivec2 outputSize, OutputComponent output,
            gl::GpuProfiler& profiler);

    // The last frame as linear radiance, box-averaged down to the output size, with the
    // pre-exposure (scene/Exposure.h) divided out.
    [[nodiscard]] core::Image readback() const;
    // The last frame's geometry coverage (its alpha), averaged the same way: one value in
    // [0, 1] per output pixel, rows top to bottom. What auto exposure meters.
    [[nodiscard]] std::vector<float> readbackCoverage() const;

    // RGBA32F linear radiance of the last frame times radianceScale()^-1 (alpha = geometry
    // coverage), render size: multiply by radianceScale() for W/(m^2 sr).
    const gl::Texture& radiance() const { return mTarget.color(); }
    // 1 / pre-exposure for radiometric outputs, 1 for the other debug views.
    float radianceScale() const;

    // The last frame's screen-space indirect irradiance (GiOutputs::indirect: rgb = E_ind
    // times the pre-exposure, a = view depth, 0 = empty) as the technique gave it and as the
    // temporal filter passed it on (the same texture without the filter); null without GI,
    // valid until the next render. Both come from one voxelization, whose averages depend on
    // the order its fragments arrive in, so they differ by the filter alone.
    struct IndirectImages {
        const gl::Texture* technique = nullptr;
        const gl::Texture* filtered = nullptr;
        glm::ivec2 size{0};
    };
    [[nodiscard]] IndirectImages lastIndirect() const { return mLastIndirect; }
    glm::ivec2 renderSize() const { return mRenderSize; }
    const scene::GpuScene& gpuScene() const { return *mScene; }

    // The textures and buffers this renderer holds now, a row per label (gl/MemoryRegistry.h);
    // the voxel occupancy (atlas visibility, voxel shadows) under "occupancy/".
    [[nodiscard]] std::vector<gl::MemoryItem> memory() const;
    // The last line-space build (shadow.method=linespace); zero before one.
    const LineSpaceStats& lineSpaceStats() const { return mLineSpace.stats(); }
    // The active shadow method's structure, last build and memory.
    [[nodiscard]] ShadowMethodReport shadowReport() const;
    // The VPL technique's VPLs, clamp, visibility and last resampling; nullopt in other modes.
    [[nodiscard]] std::optional<vpl::VplReport> vplReport() const;
    // The active GI technique, or nullptr in direct mode.
    const GiTechnique* technique() const { return mGi.get(); }
    // The voxel occupancy the visibility marches walk, or nullptr while no mode needs one.
    const voxel::VoxelizationManager* occupancyManager() const { return mOccupancy.get(); }

private:
    // The colour target's RGBA32F texels, GL rows (bottom to top).
    std::vector<float> readTarget() const;
    // The camera's FrameUniforms for this frame: the only write of the buffer per frame.
    void writeFrameUniforms(const scene::CameraView& camera, OutputComponent output);
    // shadow.method=voxel with shadows on: the forward pass reads the voxel occupancy.
    bool voxelShadows() const;
    // Builds or refreshes the BVH or line space the shadow method traces, if it traces one,
    // for the scene as last posed.
    void updateShadowRays(gl::GpuProfiler& profiler);
    // The scene's BVH for atlas.visibility=bvh, the atlas' near field (atlas.near_rays) and
    // vpl.visibility=bvh: built when needed and
    // bound for the GI pass; returns GiFrameInputs::bvhRayIterations (0 when not asked for).
    int updateGiBvh(gl::GpuProfiler& profiler);
    std::optional<OccupancyVolume> updateOccupancy(const scene::CameraView& camera, gl::GpuProfiler& profiler);

    // The plan for `requested`, this scene and mAllLights; mSettings is applyPlan of it and
    // mLights the lights it keeps for the GPU (shadow maps, injection, shading).
    [[nodiscard]] ResourcePlan planFor(const Settings& requested) const;

    // What the entry points allocate is recorded as this renderer's (memory()).
    gl::MemoryOwner mMemory;
    gl::MemoryOwner mOccupancyMemory{"occupancy/"};
    Settings mSettings;     // in effect: mRequested with the plan's sizes
    Settings mRequested;    // as given to init() / setSettings()
    ResourcePlan mPlan;
    std::vector<scene::Light> mAllLights;   // as given; mLights are the planned ones
    std::unique_ptr<scene::GpuScene> mScene;
    std::vector<scene::Light> mLights;
    gl::Buffer mFrameUniforms;
    gl::RenderTarget mTarget{"frame/target", {GL_RGBA32F, "frame/radiance"},
            {GL_DEPTH_COMPONENT32F, "frame/depth"}};
    // The final shading's samples with render.msaa > 1, resolved into mTarget.
    gl::RenderTarget mSamples{"frame/samples", {GL_RGBA32F, "frame/radiance_samples"},
            {GL_DEPTH_COMPONENT32F, "frame/depth_samples"}};
    OutputComponent mLastOutput = OutputComponent::Final;
    glm::ivec2 mRenderSize{0};
    ShadowPass mShadows;
    BvhShadows mBvhShadows;             // shadow.method=bvh
    LineSpaceShadows mLineSpace;        // shadow.method=linespace
    std::uint64_t mShadowGeometry = 0;   // GpuScene::geometryVersion() the maps were drawn for
    GiMode mMode = GiMode::Direct;
    std::unique_ptr<GiTechnique> mGi;
    // Voxel occupancy for the atlas' and the VPLs' visibility (atlas.visibility=voxel,
    // vpl.visibility=cascade) and the voxel shadow cones (shadow.method=voxel): a
    // scene-centred cascade, the same from every view.
    std::unique_ptr<voxel::VoxelizationManager> mOccupancy;
    gl::ShaderLibrary* mShaders = nullptr;
    const scene::Scene* mSceneDescription = nullptr;
    const scene::Scene* mPosedScene = nullptr;   // the last setPose's scene (init's before)
    ForwardPass mForward;
    TemporalFilter mTemporal;            // gi.temporal_filter
    std::uint64_t mTemporalGeometry = 0; // GpuScene::geometryVersion() of its last frame
    IndirectImages mLastIndirect;
};

} // namespace gi::render
