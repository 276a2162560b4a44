// Temporal reprojection filter of the GI technique's indirect irradiance (gi.temporal_filter,
// shaders/render/temporal_filter.comp): this frame's E_ind blended with the filter's previous
// output reprojected through the previous view, history rejected by view depth and normal
// (and clamped to the new frame's neighbourhood with gi.temporal_clamp, except for the frames
// that fade in a step of a resampled technique, GiOutputs::resampled), weighing the new frame
// at least gi.temporal_blend_moving while the geometry moves. It works on
// GiOutputs::indirect, so every technique gets it; a still camera keeps the technique's image.
// Inputs : GiOutputs::indirect (RGBA16F, rgb = E_ind W/m^2, a = view depth m), the frame UBO.
// Outputs: a texture of the same size and meaning (RGBA32F), for the forward pass.
#pragma once

#include "core/Settings.h"
#include "gl/GpuProfiler.h"
#include "gl/Objects.h"
#include "gl/ShaderLibrary.h"
#include "scene/CameraView.h"

#include <glm/glm.hpp>

#include <string>

namespace gi::render {

class TemporalFilter {
public:
    struct Inputs {
        const gl::Texture& indirect;       // this frame's E_ind + view depth
        glm::ivec2 size;                   // its texels
        const gl::Buffer& frameUniforms;   // FrameUniforms of `camera`, std140
        const scene::CameraView& camera;
        const TemporalSettings& settings;
        bool resampled = false;            // GiOutputs::resampled: fade a step in, no clip
        bool geometryMoved = false;        // the scene was posed anew: settings.blendMoving
    };

    bool init(gl::ShaderLibrary& shaders, std::string& error);
    // Filters this frame and keeps the result as the next frame's history.
    const gl::Texture& execute(const Inputs& in, gl::GpuProfiler& profiler);
    // Forgets the history: the next frame starts afresh (new technique, settings or lights).
    void reset() {
        mHasHistory = false;
        mUnclippedFrames = 0;
    }

    // Frames a step stays unclipped after a resampling: until the history holds less than
    // kResampleResidue of the light from before it, so the clip that resumes then moves the
    // image by at most that share of the step.
    static int fadeFrames(float blend);
    static constexpr float kResampleResidue = 0.05f;

private:
    gl::ProgramRef mProgram;
    // Ping-pong pairs: [mCurrent] is written this frame, the other holds the history.
    gl::Texture mIrradiance[2], mNormal[2];
    int mCurrent = 0;
    glm::ivec2 mSize{0};
    bool mHasHistory = false;
    int mUnclippedFrames = 0;   // frames left in which the history is not clipped
    glm::mat4 mPreviousViewProjection{1.0f}, mPreviousView{1.0f};
};

} // namespace gi::render
