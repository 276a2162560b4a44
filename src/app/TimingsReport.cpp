#include "app/TimingsReport.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>

namespace gi::app {
namespace {

// The VPLs and their last resampling (RSM and sampling run before the timed frames, so the
// pass list leaves them out), and the bytes of every "vpl/" resource.
nlohmann::json vplJson(const vpl::VplReport& r, const std::vector<gl::MemoryItem>& memory) {
    std::size_t bytes = 0;
    for (const gl::MemoryItem& item : memory) {
        if (item.name.rfind("vpl/", 0) == 0) bytes += item.bytes;
    }
    return {{"count", r.count}, {"second_generation", r.secondGeneration},
            {"clamp_m2", r.clampArea}, {"clamp_auto", r.clampFromScene},
            {"visibility", r.visibility}, {"interleave", r.interleave},
            {"rsm_views", r.rsmViews}, {"rsm_resolution", r.rsmResolution},
            {"rsm_lit_texels", r.rsmTexels}, {"rsm_ms", r.rsmMs}, {"sampling_ms", r.samplingMs},
            {"resamples", r.resamples}, {"bytes", bytes}};
}

} // namespace

std::string timingsJson(const TimingsReport& report) {
    nlohmann::json passes = nlohmann::json::array();
    for (const gl::PassTiming& pass : report.passes) {
        // A pass that ran only during warm-up (cached shadow maps) has no timed samples.
        if (pass.samples == 0) continue;
        passes.push_back({{"name", pass.name}, {"gpu_ms_median", pass.gpuMsMedian},
                {"gpu_ms_mean", pass.gpuMsAverage}, {"cpu_ms_mean", pass.cpuMsAverage},
                {"samples", pass.samples}});
    }
    nlohmann::json memory = nlohmann::json::object();
    std::size_t total = 0;
    for (const gl::MemoryItem& item : report.memory) {
        memory[item.name] = item.bytes;
        total += item.bytes;
    }
    const render::ShadowMethodReport& sh = report.shadows;
    const nlohmann::json shadows = {{"method", sh.method}, {"rays", sh.rays},
            {"structure", sh.structure}, {"build_ms", sh.buildMs}, {"bytes", sh.bytes}};
    nlohmann::json json = {{"scene", report.scene}, {"mode", report.mode},
            {"gl_provider", report.provider}, {"gl_renderer", report.renderer},
            {"timing", report.timing}, {"width", report.width}, {"height", report.height}, {"frames", report.frames},
            {"passes", passes}, {"memory_bytes", memory}, {"memory_bytes_total", total},
            {"shadows", shadows}};
    if (report.vpl) json["vpl"] = vplJson(*report.vpl, report.memory);
    return json.dump(2) + "\n";
}

bool writeTimingsJson(const std::string& path, const TimingsReport& report, std::string& error) {
    const std::string temporary = path + ".partial";
    {
        std::ofstream out(temporary);
        out << timingsJson(report);
        if (!out) {
            std::filesystem::remove(temporary);
            error = path + ": cannot write timings file";
            return false;
        }
    }
    std::error_code ec;
    std::filesystem::rename(temporary, path, ec);
    if (ec) {
        std::filesystem::remove(temporary, ec);
        error = path + ": cannot write timings file";
        return false;
    }
    return true;
}

} // namespace gi::app
