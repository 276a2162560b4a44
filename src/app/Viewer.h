// `voxatlas view`: the interactive window (GLFW, GL 4.5 core) with a fly camera, hotkeys and
// an ImGui overlay of frame and per-pass GPU times, a frame-time budget that lowers the render
// resolution while the camera moves, and scenes opened by dropping files on the window.
// Scripted runs (--frames, --keys, --move, --drop, --screenshot, --hdr) make it testable under
// Xvfb. Without a display it says so and renders a headless screenshot instead.
#pragma once

#include "app/CommandLine.h"

namespace gi::app {

[[nodiscard]] int runViewer(const Config& config);

} // namespace gi::app
