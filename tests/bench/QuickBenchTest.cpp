// The bench test: `voxatlas bench --quick` exactly as a user runs it, over the Cornell
// box and Sponza (from ../shared/assets or $VOXATLAS_SPONZA; without it the bench measures
// the Cornell box alone and this test says so). The CSV must have every column, finite
// values, and every mode on every scene measured. It takes 5 to 10 minutes on 2 cores, hence
// its own label and time limit.
#include "BenchOutput.h"
#include "GpuTest.h"
#include "Process.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <set>

namespace gi::test {
namespace {

namespace fs = std::filesystem;

TEST(QuickBench, CoversBothScenesAndEveryModeWithFiniteFigures) {
    const std::string sponza = sponzaPathOrSkip();
    const std::string dir = makeTempDir("bench-quick");
    std::vector<std::string> args = {"bench", "--quick", "--out-dir", dir + "/out"};
    if (!sponza.empty()) args.insert(args.end(), {"--scene", sponza});
    // A private reference cache: the run pays for its own references, as on a fresh machine.
    const ProcessResult r = runVoxatlas(args, 1500, {"VOXATLAS_CACHE_DIR=" + dir + "/cache"});
    ASSERT_FALSE(r.timedOut) << "bench --quick did not finish in 25 minutes";
    ASSERT_EQ(r.exitCode, 0) << r.out << r.err;

    const BenchTable table = readBenchCsv(dir + "/out/bench.csv");
    ASSERT_FALSE(table.header.empty()) << "no bench.csv";
    expectCompleteAndFinite(table);

    std::set<std::string> scenes = {"cornell_box"};
    if (!sponza.empty()) scenes.insert("Sponza");
    EXPECT_EQ(table.distinct("scene"), scenes);
    for (const std::string& scene : scenes) {
        EXPECT_EQ(table.distinct("mode", "scene", scene),
                (std::set<std::string>{"direct", "voxel", "atlas"}))
                << "a mode is missing on " << scene;
    }
    EXPECT_TRUE(table.distinct("series").count("atlas progressive"));
    // Each scene's error is scored against a reference that was actually rendered.
    for (std::size_t row = 0; row < table.rows.size(); ++row) {
        EXPECT_GT(std::stod(table.field(row, "reference_spp")), 0.0);
    }
    EXPECT_TRUE(fs::exists(dir + "/out/bench.md"));
    fs::remove_all(dir);
}

} // namespace
} // namespace gi::test
