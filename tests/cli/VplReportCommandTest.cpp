// What VPL mode reports about itself: every pass and buffer in `render --timings`, the VPLs'
// last resampling (which runs before the timed frames), the memory `info` plans for it, and
// its debug views through --output.
#include "Process.h"

#include "core/ImageIO.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

namespace gi::test {
namespace {

namespace fs = std::filesystem;

const std::string kCornell = std::string(VOXATLAS_DATA_DIR) + "/assets/cornell_box/cornell_box.gltf";

nlohmann::json readJson(const std::string& path) {
    std::ifstream in(path);
    return nlohmann::json::parse(in);
}

bool hasPassStartingWith(const nlohmann::json& passes, const std::string& prefix) {
    for (const auto& pass : passes) {
        if (pass["name"].get<std::string>().rfind(prefix, 0) == 0 &&
                pass["samples"].get<int>() > 0 && pass["gpu_ms_median"].get<double>() > 0.0) {
            return true;
        }
    }
    return false;
}

// The "    vpl/NAME   X.XXX MiB" rows of `info`.
std::map<std::string, std::string> plannedRows(const std::string& infoOut) {
    std::map<std::string, std::string> rows;
    std::istringstream lines(infoOut);
    std::string line;
    while (std::getline(lines, line)) {
        char name[64], mebibytes[32];
        if (std::sscanf(line.c_str(), " %63s %31s MiB", name, mebibytes) == 2 &&
                std::string(name).rfind("vpl/", 0) == 0) {
            rows[name] = mebibytes;
        }
    }
    return rows;
}

std::string mebibytesText(std::size_t bytes) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3f", double(bytes) / (1024.0 * 1024.0));
    return text;
}

TEST(VplReportCommand, TimingsListEveryPassTheResamplingAndTheBuffersInfoPlans) {
    const std::string dir = makeTempDir("vpl-timings");
    // 512 x 512, render's default size, which is what `info` plans for; no occupancy march
    // and few VPLs keep the gather cheap on llvmpipe.
    const std::vector<std::string> settings = {"--set", "vpl.visibility=none", "--set",
            "vpl.count=64"};
    std::vector<std::string> args = {"render", kCornell, "--mode", "vpl", "--out",
            dir + "/a.png", "--timings", dir + "/t.json", "--set", "render.warmup=1", "--set",
            "render.frames=2"};
    args.insert(args.end(), settings.begin(), settings.end());
    const ProcessResult r = runVoxatlas(args);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const nlohmann::json timings = readJson(dir + "/t.json");

    // The per-frame passes are timed; RSM and sampling ran in the warm-up frame.
    for (const char* pass : {"vpl/gbuffer", "vpl/gather", "vpl/filter"}) {
        EXPECT_TRUE(hasPassStartingWith(timings["passes"], pass)) << pass << " not timed";
    }
    ASSERT_TRUE(timings.contains("vpl")) << timings.dump();
    const nlohmann::json& vpl = timings["vpl"];
    EXPECT_EQ(vpl["count"], 64);
    EXPECT_EQ(vpl["visibility"], "none");
    EXPECT_GT(vpl["clamp_m2"].get<double>(), 0.0);
    EXPECT_EQ(vpl["rsm_views"], 6) << "a point light's six cube faces";
    EXPECT_GT(vpl["rsm_ms"].get<double>(), 0.0);
    EXPECT_GE(vpl["sampling_ms"].get<double>(), 0.0);
    EXPECT_EQ(vpl["resamples"], 1) << "a static scene draws its VPLs once";

    // Every VPL resource is in the memory table, and what `info` plans is what was allocated.
    std::vector<std::string> infoArgs = {"info", kCornell};
    infoArgs.insert(infoArgs.end(), settings.begin(), settings.end());
    const ProcessResult info = runVoxatlas(infoArgs);
    ASSERT_EQ(info.exitCode, 0) << info.err;
    const std::map<std::string, std::string> planned = plannedRows(info.out);
    ASSERT_FALSE(planned.empty()) << info.out;
    std::size_t vplBytes = 0;
    for (const auto& [name, bytes] : timings["memory_bytes"].items()) {
        if (name.rfind("vpl/", 0) != 0) continue;
        vplBytes += bytes.get<std::size_t>();
        ASSERT_TRUE(planned.count(name)) << name << " allocated but not in info's plan";
        EXPECT_EQ(planned.at(name), mebibytesText(bytes.get<std::size_t>())) << name;
    }
    for (const auto& [name, mebibytes] : planned) {
        EXPECT_TRUE(timings["memory_bytes"].contains(name)) << name << " planned, not allocated";
    }
    EXPECT_EQ(vpl["bytes"].get<std::size_t>(), vplBytes);
    fs::remove_all(dir);
}

} // namespace
} // namespace gi::test
