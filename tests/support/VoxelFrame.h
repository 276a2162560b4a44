// One voxel-GI frame of a scene rendered for GPU tests that read the voxels back or march them:
// the renderer stays alive, so its volumes stay valid until the frame is destroyed.
#pragma once

#include "GpuTest.h"

#include "gi/voxel/VoxelizationManager.h"
#include "render/FrameRenderer.h"
#include "scene/CameraView.h"

namespace gi::test {

// One voxel-GI frame of `scene` from its camera 0.
class VoxelFrame {
public:
    VoxelFrame(const scene::Scene& scene, const Settings& settings, glm::ivec2 size,
            render::OutputComponent output = render::OutputComponent::Final) {
        std::string error;
        EXPECT_TRUE(mRenderer.init(scene, settings, mShaders, error)) << error;
        EXPECT_TRUE(mRenderer.setMode(render::GiMode::Voxel, error)) << error;
        const scene::CameraView camera = scene::cameraFromScene(scene.cameras[0],
                float(size.x) / float(size.y), scene.bounds);
        gl::GpuProfiler profiler;
        mRenderer.render(camera, size, output, profiler);
        profiler.flush();
    }
    const voxel::VoxelizationManager& manager() const {
        return static_cast<const voxel::VoxelizationManager&>(*mRenderer.technique());
    }
    core::Image image() const { return mRenderer.readback(); }
    const render::FrameRenderer& renderer() const { return mRenderer; }
    // The factor the volumes' irradiance carries (scene/Exposure.h).
    float exposure() const { return mRenderer.gpuScene().exposure(); }

private:
    gl::ShaderLibrary mShaders;
    render::FrameRenderer mRenderer;
};

} // namespace gi::test
