// `voxatlas bench --sweep smoke` as CI runs it: the bench's CI form, over the Cornell box and
// Sponza, with one or two configurations per mode (the --quick and full sweeps behind
// docs/results/ measure many more, for minutes to tens of minutes). The CSV must have every
// column, finite values, and every mode on both scenes measured against a reference rendered
// in the run. About 4 minutes on 2 cores; its own label keeps it out of `ctest -LE bench`.
#include "BenchOutput.h"
#include "GpuTest.h"
#include "Process.h"
#include "Sponza.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <set>

namespace gi::test {
namespace {

namespace fs = std::filesystem;

TEST(SmokeBench, CoversBothScenesAndEveryModeWithFiniteFigures) {
    VOXATLAS_SPONZA_OR_SKIP(sponza);
    const std::string dir = makeTempDir("bench-smoke-sponza");
    const std::vector<std::string> args = {"bench", "--sweep", "smoke", "--scene", sponza,
            "--out-dir", dir + "/out"};
    // A private reference cache: the run pays for its own references, as on a fresh machine.
    // Twice the longest run seen on a loaded machine, so one slow machine does not turn the
    // build red.
    constexpr int kTimeoutSeconds = 600;
    const ProcessResult r = runVoxatlas(args, kTimeoutSeconds, {"VOXATLAS_CACHE_DIR=" + dir + "/cache"});
    ASSERT_FALSE(r.timedOut) << "bench --sweep smoke did not finish in " << kTimeoutSeconds << " s";
    ASSERT_EQ(r.exitCode, 0) << r.out << r.err;

    const BenchTable table = readBenchCsv(dir + "/out/bench.csv");
    ASSERT_FALSE(table.header.empty()) << "no bench.csv";
    expectCompleteAndFinite(table);

    const std::set<std::string> scenes = {"cornell_box", "Sponza"};
    EXPECT_EQ(table.distinct("scene"), scenes);
    for (const std::string& scene : scenes) {
        EXPECT_EQ(table.distinct("mode", "scene", scene),
                (std::set<std::string>{"direct", "voxel", "atlas", "vpl"}))
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
