// The VPL line of the viewer's overlay and the memory `info` plans for VPL mode.
#include "gi/vpl/VplReport.h"

#include <gtest/gtest.h>

namespace gi::vpl {
namespace {

TEST(VplReport, OverlayLineHasCountClampVisibilityAndEveryPass) {
    VplReport report;
    report.count = 1024;
    report.clampArea = 3.7e-4f;
    report.visibility = "cascade";
    report.rsmViews = 6;
    report.rsmResolution = 128;
    report.rsmMs = 192.5;
    report.samplingMs = 0.9;
    std::vector<gl::PassTiming> passes = {{"vpl/gbuffer", 0.5, 0.5, 0.1, 3},
            {"vpl/gather_cascade", 6.25, 6.0, 0.1, 3}, {"vpl/filter", 0.2, 0.2, 0.1, 3},
            {"render/forward", 1.0, 1.0, 0.1, 3}};
    const std::string line = describeVpl(report, passes);
    for (const char* part : {"1024 VPLs", "B 0.00037 m^2 (auto)", "visibility cascade",
                 "4x4 tiles", "RSM 6 views 128x128 192.5 ms", "sampling 0.9 ms",
                 "gbuffer 0.50 ms", "gather 6.25 ms", "filter 0.20 ms"}) {
        EXPECT_NE(line.find(part), std::string::npos) << part << " not in: " << line;
    }
    EXPECT_EQ(line.find("forward"), std::string::npos) << line;
}

TEST(VplReport, PlannedMemoryFollowsTheRenderSizeAndTheVplCount) {
    VplSettings settings;
    settings.count = 1000;
    settings.rsmResolution = 64;
    std::size_t screen = 0, rsm = 0, vpls = 0;
    for (const gl::MemoryItem& item : plannedVplMemory(settings, {100, 50})) {
        if (item.name.rfind("vpl/rsm_", 0) == 0) rsm += item.bytes;
        else if (item.name == "vpl/vpls") vpls = item.bytes;
        else if (item.name.find("uniforms") == std::string::npos &&
                item.name.find("svo_") == std::string::npos) {
            screen += item.bytes;
        }
    }
    // RGBA32F + RGBA16F + RGBA32F + depth32 per RSM texel; RGBA32F + RGBA16F + depth32 +
    // RGBA32F (the gather's sums) + RGBA16F per pixel; three vec4 per VPL.
    EXPECT_EQ(rsm, std::size_t(64 * 64) * (16 + 8 + 16 + 4));
    EXPECT_EQ(screen, std::size_t(100 * 50) * (16 + 8 + 4 + 16 + 8));
    EXPECT_EQ(vpls, std::size_t(1000) * 48);
}

} // namespace
} // namespace gi::vpl
