// `voxatlas bench --temporal --quick`, the CI form of the temporal-stability page: the Cornell
// box sideways and the animated cube in voxel and atlas mode, with and without the temporal
// filter. The page must hold a finite figure for every configuration and its pictures, the
// filter must lower the indirect term's frame-to-frame change in both modes, and no
// configuration may leave a trail above 2 % of the floor's light after 4 held frames.
#include "BenchOutput.h"
#include "Process.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <sstream>

namespace gi::test {
namespace {

namespace fs = std::filesystem;

// The cells of the markdown table rows that start with "| <label> |", by label, from the
// first table after `heading`.
std::map<std::string, std::vector<std::string>> tableRows(const std::string& markdown,
        const std::string& heading) {
    std::map<std::string, std::vector<std::string>> rows;
    const std::size_t start = markdown.find(heading);
    if (start == std::string::npos) return rows;
    std::istringstream in(markdown.substr(start));
    bool inTable = false;
    for (std::string line; std::getline(in, line);) {
        if (line.rfind("|", 0) != 0) {
            if (inTable) break;
            continue;
        }
        inTable = true;
        std::vector<std::string> cells;
        std::istringstream cellsIn(line.substr(1));
        for (std::string cell; std::getline(cellsIn, cell, '|');) {
            const std::size_t a = cell.find_first_not_of(' ');
            const std::size_t b = cell.find_last_not_of(' ');
            cells.push_back(a == std::string::npos ? "" : cell.substr(a, b - a + 1));
        }
        if (!cells.empty()) rows[cells.front()] = cells;
    }
    return rows;
}

double percentCell(const std::string& cell) { return std::stod(cell); }

TEST(TemporalBench, QuickFormWritesFiguresTheFilterLowersFlickerAndNoTrailStays) {
    const std::string dir = makeTempDir("bench-temporal");
    const ProcessResult r = runVoxatlas({"bench", "--temporal", "--quick", "--out-dir", dir},
            // About 40 s on 2 llvmpipe cores.
            280, {"VOXATLAS_CACHE_DIR=" + dir + "/cache"});
    ASSERT_FALSE(r.timedOut);
    ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
    const std::string markdown = readTextFile(dir + "/results-temporal.md");
    ASSERT_FALSE(markdown.empty()) << "no results-temporal.md";
    EXPECT_TRUE(fs::exists(dir + "/images/temporal_cornell_sideways.png"));
    EXPECT_TRUE(fs::exists(dir + "/images/temporal_moving_cube.png"));

    const auto flicker = tableRows(markdown, "## cornell_sideways");
    for (const std::string mode : {"voxel", "atlas"}) {
        ASSERT_TRUE(flicker.count(mode) && flicker.count(mode + " + filter")) << markdown;
        const double plain = percentCell(flicker.at(mode)[1]);
        const double filtered = percentCell(flicker.at(mode + " + filter")[1]);
        const double direct = percentCell(flicker.at(mode)[2]);
        EXPECT_TRUE(std::isfinite(plain) && plain > 0.0) << mode;
        EXPECT_GT(direct, 0.0) << mode;
        EXPECT_LT(filtered, plain) << mode << ": the filter did not lower the flicker";
    }
    const auto ghost = tableRows(markdown, "## Moving cube");
    for (const std::string label : {"voxel", "voxel + filter", "atlas", "atlas + filter"}) {
        ASSERT_TRUE(ghost.count(label)) << markdown;
        const std::vector<std::string>& cells = ghost.at(label);
        ASSERT_EQ(cells.size(), 8u) << label;
        EXPECT_GT(std::stod(cells[1]), 0.0) << label << ": no floor light";
        for (std::size_t i = 3; i < cells.size(); ++i) {
            EXPECT_TRUE(std::isfinite(percentCell(cells[i]))) << label;
        }
        // The target: no trail brighter than 2 % of the floor's light after 4 held
        // frames. The atlas with the filter gave 3.09 % here while the filter held back the
        // atlas' own accumulation after the cube stopped (GiOutputs::converging).
        EXPECT_LE(percentCell(cells[7]), 2.0) << label << ": trail after 4 frames";
    }
    fs::remove_all(dir);
}

} // namespace
} // namespace gi::test
