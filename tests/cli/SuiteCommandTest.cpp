// `voxatlas bench --suite`, the accuracy scoreboard, on the command line: one small scene runs
// end to end and writes the page, the table and the picture; bad input is refused with one
// line and exit code 2. The whole suite against its thresholds is tests/accuracy/.
#include "BenchOutput.h"
#include "Process.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <set>

namespace gi::test {
namespace {

namespace fs = std::filesystem;

int lineCount(const std::string& text) {
    int lines = 0;
    for (char c : text) lines += c == '\n';
    return lines;
}

TEST(SuiteCommand, OneSceneWritesPageTableAndPicture) {
    const std::string dir = makeTempDir("suite-one");
    // A small atlas, few samples and few VPLs: this checks the command, tests/accuracy the
    // scores.
    const ProcessResult r = runVoxatlas({"bench", "--suite", "quick", "--scene",
            "closed_white_box", "--out-dir", dir, "--set", "atlas.resolution=128", "--set",
            "atlas.samples=16", "--set", "atlas.target_samples=64", "--set",
            "voxel.resolution=16", "--set", "vpl.count=64"}, 280);
    ASSERT_FALSE(r.timedOut);
    ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
    const BenchTable table = readBenchCsv(dir + "/accuracy.csv");
    ASSERT_EQ(table.rows.size(), 6u)
            << "direct, voxel, voxel quality, atlas, atlas converged, vpl";
    EXPECT_EQ(table.distinct("scene"), std::set<std::string>{"closed_white_box"});
    for (std::size_t row = 0; row < table.rows.size(); ++row) {
        EXPECT_EQ(table.field(row, "available"), "1") << table.field(row, "configuration");
        EXPECT_TRUE(std::isfinite(std::stod(table.field(row, "rel_rmse_indirect"))));
    }
    const std::string page = readTextFile(dir + "/results-accuracy.md");
    EXPECT_NE(page.find("voxatlas bench --suite quick --scene closed_white_box --set "
                        "atlas.resolution=128 --set atlas.samples=16"),
            std::string::npos) << "the page says how it was made, with the settings changed";
    EXPECT_NE(page.find("--set vpl.count=64"), std::string::npos);
    EXPECT_NE(page.find("images/accuracy_closed_white_box.png"), std::string::npos);
    EXPECT_TRUE(fs::exists(dir + "/images/accuracy_closed_white_box.png"));
    fs::remove_all(dir);
}

TEST(SuiteCommand, RejectsUnknownSceneWithTheKnownOnes) {
    const ProcessResult r = runVoxatlas({"bench", "--suite", "quick", "--scene", "kitchen"});
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_EQ(lineCount(r.err), 1) << r.err;
    EXPECT_NE(r.err.find("kitchen"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("cornell_classic"), std::string::npos) << "lists the suite: " << r.err;
}

TEST(SuiteCommand, RejectsUnknownSize) {
    const ProcessResult r = runVoxatlas({"bench", "--suite", "huge"});
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_NE(r.err.find("expected quick or full"), std::string::npos) << r.err;
}

} // namespace
} // namespace gi::test
