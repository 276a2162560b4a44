// The frame's switches as the shaders read them (shaders/common/frame.glsl: shadingModel(),
// shadowMethod(), shadowsApplied()): written into the frame uniforms every frame, and given
// as #defines to the passes that compile a program per setting of them (gl/ProgramVariants.h).
#pragma once

#include "core/Settings.h"

#include <string>
#include <vector>

namespace gi::render {

struct FrameSwitches {
    int shadingModel = 0;   // SHADING_*
    int shadowMethod = 0;   // SHADOW_METHOD_*
    bool shadows = true;    // shadow.enabled

    [[nodiscard]] static FrameSwitches of(const Settings& settings);
    // FRAME_SHADING_MODEL, FRAME_SHADOW_METHOD, FRAME_SHADOWS.
    [[nodiscard]] std::vector<std::string> defines() const;
};

} // namespace gi::render
