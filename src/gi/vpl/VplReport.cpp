#include "gi/vpl/VplReport.h"

#include "gl/Objects.h"
#include "gl/Shared.h"

#include <cstdio>

namespace gi::vpl {
namespace {

// The running mean of the first pass whose name starts with `prefix`, or -1.
double passMs(const std::vector<gl::PassTiming>& passes, const std::string& prefix) {
    for (const gl::PassTiming& pass : passes) {
        if (pass.samples > 0 && pass.name.rfind(prefix, 0) == 0) return pass.gpuMsAverage;
    }
    return -1.0;
}

} // namespace

std::string visibilityName(const VplSettings& settings) {
    Settings s;
    s.vpl = settings;
    for (const SettingSpec& spec : settingSpecs()) {
        if (spec.key == "vpl.visibility") return spec.get(s);
    }
    return std::to_string(settings.visibility);
}

std::string describeVpl(const VplReport& report, const std::vector<gl::PassTiming>& passes) {
    char text[320];
    char generations[48] = "";
    if (report.secondGeneration > 0) {
        std::snprintf(generations, sizeof generations, " (%d of the second generation)",
                report.secondGeneration);
    }
    std::snprintf(text, sizeof text,
            "VPL: %d VPLs%s, B %.3g m^2%s, visibility %s, %s | last resampling: RSM %d views "
            "%dx%d %.1f ms, sampling %.1f ms",
            report.count, generations, double(report.clampArea),
            report.clampFromScene ? " (auto)" : "",
            report.visibility.c_str(), report.interleave ? "4x4 tiles" : "every VPL per pixel",
            report.rsmViews, report.rsmResolution, report.rsmResolution, report.rsmMs,
            report.samplingMs);
    std::string line = text;
    const char* separator = " | ";
    for (const auto& [label, prefix] : {std::pair{"gbuffer", "vpl/gbuffer"},
                 std::pair{"gather", "vpl/gather"}, std::pair{"filter", "vpl/filter"}}) {
        const double ms = passMs(passes, prefix);
        if (ms < 0.0) continue;
        std::snprintf(text, sizeof text, "%s%s %.2f ms", separator, label, ms);
        line += text;
        separator = ", ";
    }
    return line;
}

std::vector<gl::MemoryItem> plannedVplMemory(const VplSettings& settings,
        glm::ivec2 renderSize) {
    const glm::ivec3 rsm(settings.rsmResolution, settings.rsmResolution, 1);
    const glm::ivec3 screen(renderSize, 1);
    return {
            {"vpl/rsm_position", gl::textureBytes(GL_RGBA32F, rsm, 1)},
            {"vpl/rsm_normal", gl::textureBytes(GL_RGBA16F, rsm, 1)},
            {"vpl/rsm_flux", gl::textureBytes(GL_RGBA32F, rsm, 1)},
            {"vpl/rsm_depth", gl::textureBytes(GL_DEPTH_COMPONENT32F, rsm, 1)},
            {"vpl/vpls", std::size_t(settings.count) * sizeof(shader::GpuVpl)},
            {"vpl/uniforms", sizeof(shader::VplUniforms)},
            {"vpl/svo_uniforms", sizeof(shader::SvoUniforms)},
            {"vpl/svo_build_state", sizeof(shader::SvoBuildState)},
            {"vpl/gbuffer_position", gl::textureBytes(GL_RGBA32F, screen, 1)},
            {"vpl/gbuffer_normal", gl::textureBytes(GL_RGBA16F, screen, 1)},
            {"vpl/gbuffer_depth", gl::textureBytes(GL_DEPTH_COMPONENT32F, screen, 1)},
            {"vpl/gathered", gl::textureBytes(GL_RGBA32F, screen, 1)},
            {"vpl/indirect", gl::textureBytes(GL_RGBA16F, screen, 1)},
    };
}

} // namespace gi::vpl
