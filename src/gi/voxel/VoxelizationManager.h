// Voxel cone tracing GI, the VoxelizationManager of the thesis (SEEDS.md section 1, thesis
// 4.3.1): every frame it re-centres the cascade on the camera, clears it, voxelizes the
// scene, injects every light, propagates to the coarser levels and traces 9 cones per pixel
// at a reduced resolution. Everything is recomputed each frame (fully dynamic).
#pragma once

#include "gi/GiTechnique.h"
#include "gi/voxel/CascadeVolume.h"
#include "gi/voxel/ConeTracePass.h"
#include "gi/voxel/IndirectFilterPass.h"
#include "gi/voxel/InjectPass.h"
#include "gi/voxel/PropagatePass.h"
#include "gi/voxel/RadiancePyramidPass.h"
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
    std::vector<gl::MemoryItem> memory() const override;
    std::string status() const override;

    // Occupancy only (for the atlas' visibility): places the cascade, clears it, voxelizes
    // and propagates coverage; no light injection, no tracing.
    void updateOccupancy(const GiFrameInputs& in, gl::GpuProfiler& profiler);
    [[nodiscard]] OccupancyVolume occupancy() const { return {mTextures.albedo, mUniforms}; }

    // For tests and the overlay.
    const CascadeVolume& volume() const { return mVolume; }
    const VoxelTextures& textures() const { return mTextures; }
    const gl::Buffer& uniforms() const { return mUniforms; }

private:
    void writeUniforms();
    void placeAndVoxelize(const GiFrameInputs& in, gl::GpuProfiler& profiler);
    std::function<void(int)> levelSetter();

    VoxelSettings mSettings;
    bool mConfigured = false;
    scene::Aabb mSceneBounds;
    std::vector<scene::Light> mLights;
    CascadeVolume mVolume;
    VoxelTextures mTextures;
    gl::Buffer mUniforms;
    shader::VoxelUniforms mUniformData{};
    float mFinestExtent = 0.0f;
    bool mShowDebug = false;

    VoxelizePass mVoxelize;
    InjectPass mInject;
    PropagatePass mPropagate;
    RadiancePyramidPass mPyramid;
    ConeTracePass mTrace;
    IndirectFilterPass mFilter;
    VoxelDebugViewPass mDebugView;
};

} // namespace gi::voxel
