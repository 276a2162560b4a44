// Trace reuse (voxel.trace_reuse): the cone trace covers one pixel of every 2x2 block per
// frame, the four in turn, and this pass makes the whole trace image from it
// (shaders/voxel/trace_reuse.comp): the traced pixels as they are, the other three from the
// previous frame's result reprojected to the surface each pixel sees now, where the previous
// frame saw that surface; elsewhere the nearest traced pixel in depth. A still camera sees
// the full trace after four frames at a quarter of its cost per frame.
// Inputs : the strided trace (ConeTracePass with stride 2; or a full trace, which is kept as
//          it is), the scene for a depth pass at the full trace size, the frame UBO and the
//          camera (this frame and, kept here, the last).
// Outputs: result(), RGBA16F at the full trace size, the layout of ConeTracePass::indirect().
#pragma once

#include "gl/GpuProfiler.h"
#include "gl/Objects.h"
#include "gl/RenderTarget.h"
#include "gl/ShaderLibrary.h"
#include "scene/CameraView.h"
#include "scene/GpuScene.h"

#include <glm/glm.hpp>

#include <string>

namespace gi::voxel {

class TraceReusePass {
public:
    struct Inputs {
        const scene::GpuScene& scene;
        const gl::Buffer& frameUniforms;   // FrameUniforms of `camera`, std140
        const scene::CameraView& camera;
        const gl::Texture& traced;         // ConeTracePass::indirect()
        int stride;                        // 2, or 1 for a frame that traced every pixel
        glm::ivec2 phase;                  // the pixel of each 2x2 block it traced
    };
    struct Outputs {
        glm::ivec2 size;                   // pixels of the whole trace (even)
    };

    bool init(gl::ShaderLibrary& shaders, std::string& error);
    void execute(const Inputs& in, const Outputs& out, gl::GpuProfiler& profiler);
    [[nodiscard]] bool hasHistory() const { return mHasHistory; }
    // The next frame starts without history (it traces every pixel).
    void dropHistory() { mHasHistory = false; }

    const gl::Texture& result() const { return mResult[1 - mCurrent]; }
    glm::ivec2 size() const { return mSize; }

private:
    void drawDepth(const Inputs& in);   // the surfaces of every pixel of the trace

    gl::ProgramRef mProgram;
    gl::ProgramRef mDepthProgram;
    gl::RenderTarget mDepth{"voxel/reuse_depth", {}, {GL_DEPTH_COMPONENT32F, "voxel/reuse_depth"}};
    // Ping-pong: [mCurrent] is written this frame, the other holds the last result.
    gl::Texture mResult[2];
    int mCurrent = 0;
    glm::ivec2 mSize{0};
    bool mHasHistory = false;
    glm::mat4 mPreviousViewProjection{1.0f}, mPreviousView{1.0f};
};

} // namespace gi::voxel
