// Voxel cone tracing GI, the VoxelizationManager of the thesis (SEEDS.md section 1, thesis
// 4.3.1): every frame it re-centres the cascade on the camera, clears it, voxelizes the
// scene, injects every light, propagates to the coarser levels (and, with voxel.anisotropic,
// builds the directional voxels) and traces the diffuse cones (ConeSet.h) at a reduced
// resolution. The thesis recomputes everything each frame (voxel.cache=0); by
// default (voxel.cache=1) work whose inputs did not change is kept:
//   - a static scene whose cascade placement and lights are unchanged is not revoxelized,
//     injected or propagated: only the cone trace runs;
//   - a scene with animated instances voxelizes its static geometry once per placement
//     (StaticVoxelCache) and, on every frame they have moved, only the animated instances,
//     then injects the lights (a paused animation costs what a static scene does);
//   - with voxel.trace_reuse (the default), while the voxels' light stands still each frame
//     traces one pixel of every 2x2 block and reprojects the others (TraceReusePass).
#pragma once

#include "gi/GiTechnique.h"
#include "gi/voxel/BouncePass.h"
#include "gi/voxel/CascadeVolume.h"
#include "gi/voxel/ConeTracePass.h"
#include "gi/voxel/TraceReusePass.h"
#include "gi/voxel/DirectionalVoxelsPass.h"
#include "gi/voxel/EdgeFacesPass.h"
#include "gi/voxel/EmptyDistancePass.h"
#include "gi/voxel/IndirectFilterPass.h"
#include "gi/voxel/InjectPass.h"
#include "gi/voxel/PropagatePass.h"
#include "gi/voxel/RadiancePyramidPass.h"
#include "gi/voxel/StaticVoxelCache.h"
#include "gi/voxel/VoxelDebugViewPass.h"
#include "gi/voxel/VoxelTextures.h"
#include "gi/voxel/VoxelizePass.h"
#include "gl/Shared.h"

namespace gi::voxel {

class VoxelizationManager final : public GiTechnique {
public:
    const char* name() const override { return "voxel"; }
    bool init(gl::ShaderLibrary& shaders, const scene::Scene& scene, std::string& error) override;
    bool configure(const Settings& settings, std::string& error) override;
    void update(const GiFrameInputs& in, gl::GpuProfiler& profiler) override;
    GiOutputs outputs() const override;
    std::string status() const override;
    // The diagonal of the coarsest cascade level.
    float gatherReach() const override;

    // Occupancy only (for the atlas' visibility): places the cascade, clears it, voxelizes,
    // propagates coverage and finds the edge voxels' faces; no light injection, no tracing.
    void updateOccupancy(const GiFrameInputs& in, gl::GpuProfiler& profiler);
    [[nodiscard]] OccupancyVolume occupancy() const {
        return {mTextures.albedo, mTextures.normal, mTextures.irradiance, mTextures.edgeFaces,
                mUniforms, mContentVersion, mVolume.levels()};
    }
    // How many frames reused the previous frame's voxels and light (for tests and reports).
    [[nodiscard]] std::uint64_t reusedFrames() const { return mReusedFrames; }

    // For tests and the overlay.
    const CascadeVolume& volume() const { return mVolume; }
    const VoxelTextures& textures() const { return mTextures; }
    const gl::Buffer& uniforms() const { return mUniforms; }

private:
    // Writes VoxelUniforms for this frame's placement and settings: the only write of the
    // buffer; what changes between dispatches (level, light view) the passes set themselves.
    void writeUniforms();
    // What the voxel textures hold, and for which inputs.
    enum class Content { None, Occupancy, Lit };
    // Places the cascade for this frame; forgets the textures' content if it moved.
    void place(const GiFrameInputs& in);
    // True if the textures already hold `content` for this frame's inputs.
    [[nodiscard]] bool contentReusable(const GiFrameInputs& in, Content content) const;
    void rememberContent(const GiFrameInputs& in, Content content);
    // Clears and voxelizes the scene, its static part from the cache where possible.
    void voxelize(const GiFrameInputs& in, gl::GpuProfiler& profiler);
    void injectAndPropagate(const GiFrameInputs& in, gl::GpuProfiler& profiler);
    void trace(const GiFrameInputs& in, gl::GpuProfiler& profiler);

    VoxelSettings mSettings;
    int mBounces = 1;   // gi.bounces
    // material.model=gltf: surfaces reflect with the glTF BRDF (voxel_reflectance.glsl) and
    // ConeTracePass traces one more cone, the specular one.
    bool mGlossyMaterials = false;
    bool mConfigured = false;
    scene::Aabb mSceneBounds;
    CascadeVolume mVolume;
    VoxelTextures mTextures;
    gl::Buffer mUniforms;
    float mFinestExtent = 0.0f;
    bool mShowDebug = false;
    bool mPlacementMoved = false;   // this frame's placement differs from the last frame's

    StaticVoxelCache mStaticCache;
    bool mStaticCacheValid = false;   // mStaticCache holds this placement's static geometry
    Content mContent = Content::None;
    std::vector<scene::Light> mContentLights;
    const scene::GpuScene* mContentScene = nullptr;
    std::uint64_t mContentGeometry = 0;
    std::uint64_t mContentVersion = 0;
    std::uint64_t mReusedFrames = 0;
    std::uint64_t mTracedContent = 0;   // mContentVersion of the last frame traced
    unsigned mReusePhase = 0;           // frames traced at a quarter, picks the pixel
    bool mQuarterTraced = false;        // this frame traced a quarter of the pixels

    VoxelizePass mVoxelize;
    InjectPass mInject;
    PropagatePass mPropagate;
    BouncePass mBounce;
    DirectionalVoxelsPass mDirectional;
    EmptyDistancePass mEmptyDistance;
    EdgeFacesPass mEdgeFaces;
    RadiancePyramidPass mPyramid;
    ConeTracePass mTrace;
    TraceReusePass mReuse;
    IndirectFilterPass mFilter;
    VoxelDebugViewPass mDebugView;
};

} // namespace gi::voxel
