// Reads what `voxatlas bench` wrote (bench.csv, bench.md) and checks it the way a user's
// script would read it: every documented column present, every number finite, one row per
// configuration. Shared by the smoke test (cli) and the full `--quick` run (bench label).
#pragma once

#include <map>
#include <set>
#include <string>
#include <vector>

namespace gi::test {

struct BenchTable {
    std::vector<std::string> header;
    std::vector<std::vector<std::string>> rows;

    [[nodiscard]] bool hasColumn(const std::string& name) const;
    [[nodiscard]] const std::string& field(std::size_t row, const std::string& column) const;
    // The distinct values of one column, e.g. the modes measured.
    [[nodiscard]] std::set<std::string> distinct(const std::string& column) const;
    // Same, restricted to rows whose `filterColumn` equals `filterValue`.
    [[nodiscard]] std::set<std::string> distinct(const std::string& column,
            const std::string& filterColumn, const std::string& filterValue) const;
};

// Splits one CSV line; fields may be quoted, with "" for a literal quote.
[[nodiscard]] std::vector<std::string> splitCsvLine(const std::string& line);

// Reads a CSV file; an unreadable file gives an empty table.
[[nodiscard]] BenchTable readBenchCsv(const std::string& path);

[[nodiscard]] std::string readTextFile(const std::string& path);

// Adds a gtest failure for each missing column, each row of the wrong width and each
// numeric field (frame and pass times, memory, errors) that is empty or not finite.
void expectCompleteAndFinite(const BenchTable& table);

} // namespace gi::test
