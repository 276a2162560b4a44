#include "BenchOutput.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace gi::test {

bool BenchTable::hasColumn(const std::string& name) const {
    return std::find(header.begin(), header.end(), name) != header.end();
}

const std::string& BenchTable::field(std::size_t row, const std::string& column) const {
    static const std::string missing;
    const auto it = std::find(header.begin(), header.end(), column);
    if (it == header.end() || row >= rows.size()) return missing;
    const auto index = static_cast<std::size_t>(it - header.begin());
    return index < rows[row].size() ? rows[row][index] : missing;
}

std::set<std::string> BenchTable::distinct(const std::string& column) const {
    std::set<std::string> values;
    for (std::size_t r = 0; r < rows.size(); ++r) values.insert(field(r, column));
    return values;
}

std::set<std::string> BenchTable::distinct(const std::string& column,
        const std::string& filterColumn, const std::string& filterValue) const {
    std::set<std::string> values;
    for (std::size_t r = 0; r < rows.size(); ++r) {
        if (field(r, filterColumn) == filterValue) values.insert(field(r, column));
    }
    return values;
}

std::vector<std::string> splitCsvLine(const std::string& line) {
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

BenchTable readBenchCsv(const std::string& path) {
    BenchTable table;
    std::ifstream in(path);
    std::string line;
    if (!std::getline(in, line)) return table;
    table.header = splitCsvLine(line);
    while (std::getline(in, line)) {
        if (!line.empty()) table.rows.push_back(splitCsvLine(line));
    }
    return table;
}

std::string readTextFile(const std::string& path) {
    std::ifstream in(path);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

void expectCompleteAndFinite(const BenchTable& table) {
    // The columns docs/results/README.md documents for scripts.
    const std::vector<std::string> required = {"scene", "mode", "series", "config",
            "frames_accumulated", "scored_frames", "changed", "width", "height", "frame_ms",
            "frame_ratio", "direct_ratio", "gi_ms", "memory_bytes", "gi_memory_bytes",
            "rel_rmse_indirect", "rel_rmse_final", "energy_ratio_indirect",
            "reference_noise_indirect", "reference_noise_final", "reference_spp", "pareto",
            "voxel.resolution", "voxel.trace_scale", "atlas.resolution", "atlas.samples",
            "ms_render_forward"};
    for (const std::string& name : required) {
        EXPECT_TRUE(table.hasColumn(name)) << "missing column " << name;
    }
    std::vector<std::string> numeric = {"frame_ms", "frame_ratio", "direct_ratio", "gi_ms",
            "memory_bytes", "gi_memory_bytes", "rel_rmse_indirect", "rel_rmse_final",
            "energy_ratio_indirect", "reference_noise_indirect", "reference_noise_final"};
    for (const std::string& name : table.header) {
        if (name.rfind("ms_", 0) == 0) numeric.push_back(name);
    }
    for (std::size_t r = 0; r < table.rows.size(); ++r) {
        ASSERT_EQ(table.rows[r].size(), table.header.size()) << "row " << r;
        for (const std::string& name : numeric) {
            const std::string& text = table.field(r, name);
            char* end = nullptr;
            const double value = std::strtod(text.c_str(), &end);
            EXPECT_TRUE(!text.empty() && *end == '\0' && std::isfinite(value))
                    << name << " = '" << text << "' in row " << r << " ("
                    << table.field(r, "scene") << " " << table.field(r, "config") << ")";
        }
        EXPECT_GT(std::strtod(table.field(r, "frame_ms").c_str(), nullptr), 0.0) << "row " << r;
        EXPECT_GT(std::strtod(table.field(r, "memory_bytes").c_str(), nullptr), 0.0)
                << "row " << r;
    }
}

} // namespace gi::test
