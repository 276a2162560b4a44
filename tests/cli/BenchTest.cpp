// `voxatlas bench` end to end, limited by VOXATLAS_BENCH_SMOKE=1 to the Cornell box and a
// handful of cheap configurations so it fits a test's time: the CSV has every column, every
// number in it is finite, every mode the build can run has a row, and the markdown table and
// the frontier are there. Also the clean refusals of bad input.
#include "Process.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

namespace gi::test {
namespace {

namespace fs = std::filesystem;

// Splits one CSV line; fields may be quoted with "" for a literal quote.
std::vector<std::string> splitCsv(const std::string& line) {
    std::vector<std::string> fields(1);
    bool quoted = false;
    for (std::size_t i = 0; i < line.size(); ++i) {
        const char c = line[i];
        if (quoted) {
            if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') fields.back() += '"', ++i;
            else if (c == '"') quoted = false;
            else fields.back() += c;
        } else if (c == '"') {
            quoted = true;
        } else if (c == ',') {
            fields.emplace_back();
        } else {
            fields.back() += c;
        }
    }
    return fields;
}

std::string slurp(const std::string& path) {
    std::ifstream in(path);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

TEST(BenchCommand, SmokeSweepWritesCompleteCsvAndMarkdown) {
    const std::string dir = makeTempDir("bench-smoke");
    // A private reference cache, so the test neither depends on nor fills the user's.
    const ProcessResult r = runVoxatlas({"bench", "--quick", "--out-dir", dir + "/out"},
            // The smoke sweep takes about 15 s on 2 llvmpipe cores; 170 s leaves room for a
            // loaded CI machine while staying under the 300 s ctest limit.
            170, {"VOXATLAS_BENCH_SMOKE=1", "VOXATLAS_CACHE_DIR=" + dir + "/cache"});
    ASSERT_FALSE(r.timedOut);
    ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
    EXPECT_NE(r.out.find("[1/"), std::string::npos) << "one progress line per configuration: " << r.out;
    EXPECT_NE(r.out.find("ETA"), std::string::npos) << r.out;

    std::ifstream csv(dir + "/out/bench.csv");
    ASSERT_TRUE(csv) << "no bench.csv";
    std::string line;
    ASSERT_TRUE(std::getline(csv, line));
    const std::vector<std::string> header = splitCsv(line);
    std::map<std::string, std::size_t> column;
    for (std::size_t i = 0; i < header.size(); ++i) column[header[i]] = i;
    const std::vector<std::string> required = {"scene", "mode", "series", "config", "changed",
            "width", "height", "frame_ms", "frame_ratio", "direct_ratio", "gi_ms", "memory_bytes",
            "gi_memory_bytes", "rel_rmse_indirect", "rel_rmse_final", "energy_ratio_indirect",
            "reference_noise_indirect", "reference_noise_final", "reference_spp", "pareto",
            "voxel.resolution", "voxel.trace_scale", "atlas.resolution", "atlas.samples",
            "ms_render_forward"};
    for (const std::string& name : required) EXPECT_TRUE(column.count(name)) << "missing column " << name;
    std::vector<std::string> numeric = {"frame_ms", "frame_ratio", "direct_ratio", "gi_ms", "memory_bytes",
            "gi_memory_bytes", "rel_rmse_indirect", "rel_rmse_final", "energy_ratio_indirect",
            "reference_noise_indirect", "reference_noise_final"};
    for (const std::string& name : header) {
        if (name.rfind("ms_", 0) == 0) numeric.push_back(name);
    }

    std::set<std::string> modes;
    std::set<std::string> frontierSeries;
    int rows = 0;
    while (std::getline(csv, line)) {
        if (line.empty()) continue;
        ++rows;
        const std::vector<std::string> fields = splitCsv(line);
        ASSERT_EQ(fields.size(), header.size()) << line;
        modes.insert(fields[column["mode"]]);
        EXPECT_EQ(fields[column["scene"]], "cornell_box");
        for (const std::string& name : numeric) {
            const std::string& text = fields[column[name]];
            char* end = nullptr;
            const double value = std::strtod(text.c_str(), &end);
            EXPECT_TRUE(!text.empty() && *end == '\0' && std::isfinite(value))
                    << name << " = '" << text << "' in: " << line;
        }
        EXPECT_GT(std::strtod(fields[column["frame_ms"]].c_str(), nullptr), 0.0) << line;
        EXPECT_GT(std::strtod(fields[column["memory_bytes"]].c_str(), nullptr), 0.0) << line;
        if (fields[column["pareto"]] == "1") frontierSeries.insert(fields[column["series"]]);
    }
    // The smoke sweep has the direct baseline and two configurations per GI mode; a mode the
    // build cannot run is listed under "Not measured" in bench.md instead.
    const std::string markdown = slurp(dir + "/out/bench.md");
    EXPECT_TRUE(modes.count("direct")) << "no direct-light baseline row";
    EXPECT_TRUE(modes.count("voxel")) << "no voxel row";
    const bool atlasSkipped = markdown.find("atlas unavailable") != std::string::npos;
    EXPECT_TRUE(modes.count("atlas") || atlasSkipped) << "no atlas row and no reason: " << markdown;
    EXPECT_GE(rows, 3);
    // Direct light alone is the only configuration of its series: always on its frontier.
    EXPECT_TRUE(frontierSeries.count("direct"));

    EXPECT_NE(markdown.find("## cornell_box"), std::string::npos) << markdown;
    EXPECT_NE(markdown.find("◆"), std::string::npos) << markdown;
    EXPECT_NE(markdown.find("Frontier steps"), std::string::npos) << markdown;
    // pareto.png depends on /usr/bin/python3 with matplotlib; without it the bench says so.
    EXPECT_TRUE(fs::exists(dir + "/out/pareto.png") ||
                r.err.find("plot skipped") != std::string::npos) << r.err;
    for (const auto& entry : fs::directory_iterator(dir + "/out")) {
        EXPECT_NE(entry.path().extension(), ".tmp") << "temporary file left behind: " << entry.path();
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
