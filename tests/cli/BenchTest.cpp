// `voxatlas bench --sweep smoke` on the Cornell box alone (--scene names it), a handful of
// cheap configurations for a quick signal: the CSV has every column, every number in it is
// finite, every mode the build can run has a row, and the markdown table and the frontier are
// there. Also the clean refusals of bad input. The same sweep over Sponza too runs under the
// `bench` label (tests/bench/SmokeBenchTest.cpp).
#include "BenchOutput.h"
#include "Process.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <set>

namespace gi::test {
namespace {

namespace fs = std::filesystem;

TEST(BenchCommand, SmokeSweepWritesCompleteCsvAndMarkdown) {
    const std::string dir = makeTempDir("bench-smoke");
    // A private reference cache, so the test neither depends on nor fills the user's.
    const ProcessResult r = runVoxatlas({"bench", "--sweep", "smoke", "--scene",
            std::string(VOXATLAS_DATA_DIR) + "/assets/cornell_box/cornell_box.gltf", "--out-dir",
            dir + "/out"},
            // The smoke sweep of the Cornell box alone takes about 15 s on 2 llvmpipe cores;
            // 170 s leaves room for a loaded CI machine while staying under the 300 s limit.
            170, {"VOXATLAS_CACHE_DIR=" + dir + "/cache"});
    ASSERT_FALSE(r.timedOut);
    ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
    EXPECT_NE(r.out.find("[1/"), std::string::npos)
            << "one progress line per configuration: " << r.out;
    EXPECT_NE(r.out.find("ETA"), std::string::npos) << r.out;

    const BenchTable table = readBenchCsv(dir + "/out/bench.csv");
    ASSERT_FALSE(table.header.empty()) << "no bench.csv";
    expectCompleteAndFinite(table);
    EXPECT_EQ(table.distinct("scene"), std::set<std::string>{"cornell_box"});
    const std::set<std::string> modes = table.distinct("mode");
    const std::set<std::string> frontierSeries = table.distinct("series", "pareto", "1");
    const std::size_t rows = table.rows.size();
    // The smoke sweep has the direct baseline and two configurations per GI mode; a mode the
    // build cannot run is listed under "Not measured" in bench.md instead.
    const std::string markdown = readTextFile(dir + "/out/bench.md");
    EXPECT_TRUE(modes.count("direct")) << "no direct-light baseline row";
    EXPECT_TRUE(modes.count("voxel")) << "no voxel row";
    const bool atlasSkipped = markdown.find("atlas unavailable") != std::string::npos;
    EXPECT_TRUE(modes.count("atlas") || atlasSkipped) << "no atlas row and no reason: " << markdown;
    EXPECT_GE(rows, 3u);
    // Direct light alone is the only configuration of its series: always on its frontier.
    EXPECT_TRUE(frontierSeries.count("direct"));

    EXPECT_NE(markdown.find("## cornell_box"), std::string::npos) << markdown;
    EXPECT_NE(markdown.find("◆"), std::string::npos) << markdown;
    EXPECT_NE(markdown.find("Frontier steps"), std::string::npos) << markdown;
    // pareto.png depends on /usr/bin/python3 with matplotlib; without it the bench says so.
    EXPECT_TRUE(fs::exists(dir + "/out/pareto.png") ||
                r.err.find("plot skipped") != std::string::npos) << r.err;
    for (const auto& entry : fs::directory_iterator(dir + "/out")) {
        EXPECT_NE(entry.path().extension(), ".tmp")
                << "temporary file left behind: " << entry.path();
    }
    fs::remove_all(dir);
}

TEST(BenchCommand, RejectsMissingScene) {
    const std::string dir = makeTempDir("bench-missing-scene");
    const ProcessResult r = runVoxatlas({"bench", "--quick", "--scene", dir + "/nothere.gltf",
            "--out-dir", dir + "/out"});
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_NE(r.err.find("nothere.gltf"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir + "/out/bench.csv"));
    fs::remove_all(dir);
}

TEST(BenchCommand, RejectsBadSetting) {
    const ProcessResult r = runVoxatlas({"bench", "--quick", "--set", "voxel.resolution=3000"});
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_NE(r.err.find("voxel.resolution"), std::string::npos) << r.err;
}

} // namespace
} // namespace gi::test
