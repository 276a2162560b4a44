// What VPL mode reports about itself: every pass and buffer in `render --timings`, the VPLs'
// last resampling (which runs before the timed frames), the memory `info` plans for it, its
// debug views through --output, and its refusal of bad settings in every command.
#include "Process.h"

#include "core/ImageIO.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
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

// Each debug view renders through --output: the VPLs as coloured discs (the Cornell box's red
// and green walls give red and green VPLs), and the visibility as grey in [0, 1] with shadows.
TEST(VplReportCommand, DebugViewsRenderThroughOutput) {
    const std::string dir = makeTempDir("vpl-debug-views");
    auto render = [&](const std::string& output, std::vector<std::string> extra = {}) {
        std::vector<std::string> args = {"render", kCornell, "--mode", "vpl", "--output",
                output, "--width", "64", "--height", "64", "--out", dir + "/" + output + ".png"};
        args.insert(args.end(), extra.begin(), extra.end());
        const ProcessResult r = runVoxatlas(args);
        EXPECT_EQ(r.exitCode, 0) << output << ": " << r.err;
        core::Image image;
        std::string error;
        EXPECT_TRUE(core::readPng(dir + "/" + output + ".png", image, error)) << error;
        return image;
    };
    auto countPixels = [](const core::Image& image, auto predicate) {
        int count = 0;
        for (int y = 0; y < image.height; ++y) {
            for (int x = 0; x < image.width; ++x) count += predicate(image.at(x, y)) ? 1 : 0;
        }
        return count;
    };
    const auto reddish = [](glm::vec3 c) { return c.r > 0.5f && c.g < 0.5f * c.r; };
    const auto greenish = [](glm::vec3 c) { return c.g > 0.5f && c.r < 0.5f * c.g; };
    const core::Image points = render("vpl-points");
    EXPECT_GT(countPixels(points, reddish), 0) << "no VPL on the red wall";
    EXPECT_GT(countPixels(points, greenish), 0) << "no VPL on the green wall";

    // One class holds a sixteenth of the VPLs: fewer coloured discs than every VPL gives.
    const auto coloured = [](glm::vec3 c) {
        return std::max({c.r, c.g, c.b}) - std::min({c.r, c.g, c.b}) > 0.3f;
    };
    const core::Image subset = render("vpl-subset", {"--set", "vpl.debug_subset=3"});
    EXPECT_LT(countPixels(subset, coloured), countPixels(points, coloured));

    const core::Image visibility = render("vpl-visibility");
    EXPECT_EQ(countPixels(visibility, [](glm::vec3 c) { return c.r != c.g || c.g != c.b; }), 0)
            << "the visibility view is grey";
    EXPECT_GT(countPixels(visibility, [](glm::vec3 c) { return c.r > 0.9f; }), 64 * 64 / 4);
    EXPECT_GT(countPixels(visibility, [](glm::vec3 c) { return c.r < 0.7f; }), 0)
            << "the blocks shadow some VPLs";
    fs::remove_all(dir);
}

// Bad VPL settings are refused by every command with exit 2 and one line naming the key.
TEST(VplReportCommand, EveryCommandRefusesBadVplSettings) {
    const std::string dir = makeTempDir("vpl-refusals");
    const std::vector<std::vector<std::string>> commands = {
            {"render", kCornell, "--mode", "vpl", "--out", dir + "/a.png"},
            {"info", kCornell},
            {"bench", "--suite", "quick", "--scene", "cornell_classic", "--out-dir", dir + "/s"},
    };
    for (const auto& command : commands) {
        for (const char* bad : {"vpl.count=0", "vpl.clamp=-0.5", "vpl.debug_subset=16"}) {
            std::vector<std::string> args = command;
            args.insert(args.end(), {"--set", bad});
            const ProcessResult r = runVoxatlas(args);
            const std::string what = command[0] + " --set " + bad;
            EXPECT_EQ(r.exitCode, 2) << what << ": " << r.err;
            EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << what << ": " << r.err;
            const std::string key = std::string(bad).substr(0, std::string(bad).find('='));
            EXPECT_NE(r.err.find(key), std::string::npos) << what << ": " << r.err;
        }
    }
    EXPECT_FALSE(fs::exists(dir + "/a.png"));
    EXPECT_FALSE(fs::exists(dir + "/s"));
    fs::remove_all(dir);
}

} // namespace
} // namespace gi::test
