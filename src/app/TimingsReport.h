// The --timings JSON: per-pass GPU milliseconds (median and mean over the timed frames),
// CPU issue time, the GPU memory each resource allocated, what the shadow method built, and in
// VPL mode what the VPLs' last resampling took (it runs before the timed frames), for scripts
// and the bench.
#pragma once

#include "gi/vpl/VplReport.h"
#include "gl/GpuProfiler.h"
#include "gl/Objects.h"
#include "render/ShadowMethodReport.h"

#include <optional>
#include <string>
#include <vector>

namespace gi::app {

struct TimingsReport {
    std::string scene, mode, provider, renderer;
    std::string timing;   // "queries" (GL timestamps) or "finish" (glFinish + wall clock)
    int width = 0, height = 0, frames = 0;
    std::vector<gl::PassTiming> passes;
    std::vector<gl::MemoryItem> memory;
    render::ShadowMethodReport shadows;   // the shadow method's structure, build and memory
    std::optional<vpl::VplReport> vpl;   // --mode vpl: the VPLs and their last resampling
};

[[nodiscard]] std::string timingsJson(const TimingsReport& report);
[[nodiscard]] bool writeTimingsJson(const std::string& path, const TimingsReport& report,
        std::string& error);

} // namespace gi::app
