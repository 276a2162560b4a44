#include "bench/BenchReport.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

namespace gi::bench {
namespace {

namespace fs = std::filesystem;

std::string number(double value, const char* format = "%.6g") {
    char text[64];
    std::snprintf(text, sizeof text, format, value);
    return text;
}

std::string csvField(const std::string& text) {
    if (text.find_first_of(",\"\n") == std::string::npos) return text;
    std::string quoted = "\"";
    for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
    return quoted + "\"";
}

std::string passColumn(const std::string& pass) {
    std::string column = "ms_" + pass;
    std::replace(column.begin(), column.end(), '/', '_');
    return column;
}

// Swept setting keys present in any measurement, in the order of settingSpecs().
std::vector<std::string> settingColumns(const std::vector<BenchMeasurement>& measurements) {
    std::set<std::string> present;
    for (const BenchMeasurement& m : measurements) {
        for (const auto& [key, value] : m.settings) present.insert(key);
    }
    std::vector<std::string> keys;
    for (const SettingSpec& spec : settingSpecs()) {
        if (present.count(spec.key)) keys.push_back(spec.key);
    }
    return keys;
}

std::vector<std::string> passNames(const std::vector<BenchMeasurement>& measurements) {
    std::vector<std::string> names;
    for (const BenchMeasurement& m : measurements) {
        if (!m.available) continue;
        for (const gl::PassTiming& pass : m.passes) {
            if (std::find(names.begin(), names.end(), pass.name) == names.end()) {
                names.push_back(pass.name);
            }
        }
    }
    return names;
}

std::string seriesOf(const BenchMeasurement& m) { return seriesName(m.configuration); }

// "x1.23", or "-" when there is no ratio (its base was not measured).
std::string ratio(double value) { return value > 0.0 ? number(value, "x%.2f") : "-"; }

std::string percent(double fraction) { return number(100.0 * fraction, "%.1f") + " %"; }

std::string mebibytes(std::size_t bytes) {
    return number(double(bytes) / (1024.0 * 1024.0), "%.1f");
}

// The frontier of one scene and series, fastest first.
std::vector<const BenchMeasurement*> frontier(const std::vector<BenchMeasurement>& measurements,
        const std::string& scene, const std::string& series) {
    std::vector<const BenchMeasurement*> points;
    for (const BenchMeasurement& m : measurements) {
        if (m.available && m.pareto && m.scene == scene && seriesOf(m) == series) {
            points.push_back(&m);
        }
    }
    std::sort(points.begin(), points.end(), [](const BenchMeasurement* a,
            const BenchMeasurement* b) { return a->frameMs < b->frameMs; });
    return points;
}


std::string formatDuration(double seconds) {
    const long s = std::lround(seconds);
    return std::to_string(s / 60) + " min " + std::to_string(s % 60) + " s";
}

} // namespace

void finalizeMeasurements(std::vector<BenchMeasurement>& measurements) {
    std::map<std::pair<std::string, render::GiMode>, double> baseMs;
    for (const BenchMeasurement& m : measurements) {
        if (m.available && m.configuration.base) {
            baseMs[{m.scene, m.configuration.mode}] = m.frameMs;
        }
    }
    for (BenchMeasurement& m : measurements) {
        const auto base = baseMs.find({m.scene, m.configuration.mode});
        m.frameRatio = m.available && base != baseMs.end() && base->second > 0.0
                ? m.frameMs / base->second
                : 0.0;
        const auto direct = baseMs.find({m.scene, render::GiMode::Direct});
        m.directRatio = m.available && direct != baseMs.end() && direct->second > 0.0
                ? m.frameMs / direct->second
                : 0.0;
        m.pareto = false;
        if (!m.available || !std::isfinite(m.relRmseIndirect) || !std::isfinite(m.frameMs)) {
            continue;
        }
        // At 100 % or more the GI buys nothing: an indirect image of zeros scores exactly 100 %.
        if (m.configuration.mode != render::GiMode::Direct && m.relRmseIndirect >= 1.0) continue;
        bool dominated = false;
        for (const BenchMeasurement& other : measurements) {
            if (&other == &m || !other.available || other.scene != m.scene ||
                    seriesOf(other) != seriesOf(m) || !std::isfinite(other.relRmseIndirect)) {
                continue;
            }
            const bool noWorse =
                    other.frameMs <= m.frameMs && other.relRmseIndirect <= m.relRmseIndirect;
            const bool better =
                    other.frameMs < m.frameMs || other.relRmseIndirect < m.relRmseIndirect;
            if (noWorse && better) {
                dominated = true;
                break;
            }
        }
        m.pareto = !dominated;
    }
}

std::vector<std::string> benchCsvColumns(const std::vector<BenchMeasurement>& measurements) {
    std::vector<std::string> columns = {"scene", "mode", "series", "config", "base",
            "frames_accumulated", "scored_frames", "changed"};
    for (const std::string& key : settingColumns(measurements)) columns.push_back(key);
    for (const char* column :
            {"width", "height", "frame_ms", "frame_ratio", "direct_ratio", "gi_ms"}) {
        columns.push_back(column);
    }
    for (const std::string& pass : passNames(measurements)) columns.push_back(passColumn(pass));
    for (const char* column : {"memory_bytes", "gi_memory_bytes", "rel_rmse_indirect",
                 "rel_rmse_final", "energy_ratio_indirect", "reference_noise_indirect",
                 "reference_noise_final", "reference_spp", "pareto"}) {
        columns.push_back(column);
    }
    return columns;
}

std::string benchCsv(const std::vector<BenchMeasurement>& measurements) {
    const std::vector<std::string> keys = settingColumns(measurements);
    const std::vector<std::string> passes = passNames(measurements);
    std::ostringstream out;
    const std::vector<std::string> columns = benchCsvColumns(measurements);
    for (std::size_t i = 0; i < columns.size(); ++i) out << (i ? "," : "") << columns[i];
    out << "\n";
    for (const BenchMeasurement& m : measurements) {
        if (!m.available) continue;
        std::vector<std::string> row = {m.scene, render::giModeName(m.configuration.mode),
                seriesOf(m), m.configuration.label, m.configuration.base ? "1" : "0",
                std::to_string(std::max(1, m.configuration.accumulatedFrames)),
                std::to_string(m.scoredFrames), changesText(m.configuration)};
        for (const std::string& key : keys) {
            const auto value = m.settings.find(key);
            row.push_back(value == m.settings.end() ? "" : value->second);
        }
        row.push_back(std::to_string(m.size.x));
        row.push_back(std::to_string(m.size.y));
        row.push_back(number(m.frameMs));
        row.push_back(number(m.frameRatio));
        row.push_back(number(m.directRatio));
        row.push_back(number(m.giMs));
        for (const std::string& pass : passes) {
            double ms = 0.0;
            for (const gl::PassTiming& timing : m.passes) {
                if (timing.name == pass) ms = timing.gpuMsMedian;
            }
            row.push_back(number(ms));
        }
        row.push_back(std::to_string(m.memoryBytes));
        row.push_back(std::to_string(m.giMemoryBytes));
        row.push_back(number(m.relRmseIndirect));
        row.push_back(number(m.relRmseFinal));
        row.push_back(number(m.energyRatioIndirect));
        row.push_back(number(m.referenceNoiseIndirect));
        row.push_back(number(m.referenceNoiseFinal));
        row.push_back(std::to_string(m.referenceSpp));
        row.push_back(m.pareto ? "1" : "0");
        for (std::size_t i = 0; i < row.size(); ++i) out << (i ? "," : "") << csvField(row[i]);
        out << "\n";
    }
    return out.str();
}

namespace {

// The run: sweep, machine, frame counts, load, and how to read the tables.
void writeMarkdownHeader(std::ostream& out, const BenchRunInfo& info) {
    out << "# voxatlas bench (" << info.sweep << ")\n\n"
        << "Generated by `voxatlas bench" << (info.sweep == "quick" ? " --quick" : "") << "` on "
        << info.date << " in " << formatDuration(info.seconds) << " (references included).\n"
        << "GL: " << info.glRenderer << ", " << info.cores << " CPU cores; passes timed by "
        << info.timing << ". Each configuration: " << info.warmupFrames << " warm-up frames, "
        << "then the median of " << info.timedFrames << " timed frames; errors are the root "
        << "mean square over " << info.scoredFrames
        << " scored frames (energy ratios: the mean).\n";
    if (!info.loadBefore.empty()) {
        out << "Load average (1, 5, 15 min) at the start " << info.loadBefore << ", at the end "
            << info.loadAfter << ": with other work on the cores, timings are slower and noisier "
            << "than on a quiet machine.\n";
    }
    out
        << "`material.specular=0` everywhere (the reference is Lambertian); `voxel.cache=0`, so "
        << "voxel GI redoes every pass every frame (docs/results-adaptive.md measures static "
        << "caching). "
        << "Absolute milliseconds on llvmpipe are not GPU figures: compare the ratios "
        << "(`x base` = frame time / the mode's base configuration, `x direct` = frame time / "
        << "the direct-light-only frame, both in the same run).\n"
        << "Errors are relative RMSE over the reference's geometry pixels; see README.md for "
        << "the formulas and the noise floor.\n\n";
    for (const std::string& note : info.notes) out << "- " << note << "\n";
    if (!info.notes.empty()) out << "\n";
}

// One scene's table, fastest first; returns its rows.
std::vector<const BenchMeasurement*> writeSceneTable(std::ostream& out,
        const BenchSceneSummary& scene, const std::vector<BenchMeasurement>& measurements) {
    out << "## " << scene.name << " (" << scene.size.x << "x" << scene.size.y << ", "
        << scene.cameraText << ")\n\n"
        << "Scene `" << scene.path << "`. Reference: " << scene.referenceSpp << " spp, "
        << scene.referenceBounces << " bounce(s); its own estimated noise is "
        << number(100.0 * scene.noiseIndirect, "%.2f") << " % (indirect) and "
        << number(100.0 * scene.noiseFinal, "%.2f") << " %"
        << " (final) relative RMSE, the floor below which errors are not resolved.\n\n"
        << "| frontier | series | configuration | frame ms | x base | x direct | GI ms | "
           "GI MiB | rel. RMSE indirect | rel. RMSE final | energy ratio indirect |\n"
        << "|---|---|---|---|---|---|---|---|---|---|---|\n";
    std::vector<const BenchMeasurement*> rows;
    for (const BenchMeasurement& m : measurements) {
        if (m.scene == scene.name && m.available) rows.push_back(&m);
    }
    std::stable_sort(rows.begin(), rows.end(), [](const BenchMeasurement* a,
            const BenchMeasurement* b) { return a->frameMs < b->frameMs; });
    for (const BenchMeasurement* m : rows) {
        out << "| " << (m->pareto ? "◆" : "") << " | " << seriesOf(*m) << " | "
            << m->configuration.label << " | " << number(m->frameMs, "%.1f") << " | "
            << ratio(m->frameRatio) << " | " << ratio(m->directRatio) << " | "
            << number(m->giMs, "%.1f") << " | " << mebibytes(m->giMemoryBytes) << " | "
            << percent(m->relRmseIndirect) << " | " << percent(m->relRmseFinal) << " | "
            << number(m->energyRatioIndirect, "%.3f") << " |\n";
    }
    out << "\n◆ = on the Pareto frontier of its series: no configuration of the series is "
           "both at least as fast and at least as accurate on the indirect component, and the "
           "indirect error is under 100 % (at 100 % the GI does no better than none: direct "
           "light alone scores exactly 100 %).\n\n";
    return rows;
}

// What each step along a series' Pareto frontier costs and gains.
void writeFrontierSteps(std::ostream& out, const BenchSceneSummary& scene,
        const std::vector<const BenchMeasurement*>& rows,
        const std::vector<BenchMeasurement>& measurements) {
    std::vector<std::string> series;
    for (const BenchMeasurement* m : rows) {
        if (std::find(series.begin(), series.end(), seriesOf(*m)) == series.end()) {
            series.push_back(seriesOf(*m));
        }
    }
    out << "### Frontier steps (" << scene.name << ")\n\n";
    for (const std::string& name : series) {
        if (name == render::giModeName(render::GiMode::Direct)) continue;
        const std::vector<const BenchMeasurement*> points =
                frontier(measurements, scene.name, name);
        out << "**" << name << "**: ";
        if (points.empty()) {
            out << "no configuration under 100 % indirect error (none is better than no "
                   "GI).\n\n";
            continue;
        }
        out << "fastest is *" << points.front()->configuration.label << "* ("
            << number(points.front()->frameMs, "%.1f") << " ms, "
            << percent(points.front()->relRmseIndirect) << " indirect error).\n";
        if (points.size() > 1) out << "\n";
        for (std::size_t i = 1; i < points.size(); ++i) {
            const BenchMeasurement& a = *points[i - 1];
            const BenchMeasurement& b = *points[i];
            const double ms = b.frameMs - a.frameMs;
            const double pp = 100.0 * (a.relRmseIndirect - b.relRmseIndirect);
            out << "- *" << a.configuration.label << "* -> *" << b.configuration.label
                << "*: +" << number(ms, "%.1f") << " ms ("
                << ratio(b.frameMs / a.frameMs)
                << "), indirect error " << percent(a.relRmseIndirect) << " -> "
                << percent(b.relRmseIndirect) << ", " << number(ms / std::max(pp, 1e-9), "%.1f")
                << " ms per percentage point\n";
        }
        out << "\n";
    }
}

void writeNotMeasured(std::ostream& out, const std::vector<BenchMeasurement>& measurements) {
    std::vector<const BenchMeasurement*> skipped;
    for (const BenchMeasurement& m : measurements) {
        if (!m.available) skipped.push_back(&m);
    }
    if (skipped.empty()) return;
    out << "## Not measured\n\n";
    for (const BenchMeasurement* m : skipped) {
        out << "- " << m->scene << ", " << seriesOf(*m) << " *" << m->configuration.label
            << "*: " << m->unavailableReason << "\n";
    }
    out << "\n";
}

} // namespace

std::string benchMarkdown(const std::vector<BenchMeasurement>& measurements,
        const BenchRunInfo& info) {
    std::ostringstream out;
    writeMarkdownHeader(out, info);
    for (const BenchSceneSummary& scene : info.scenes) {
        const std::vector<const BenchMeasurement*> rows =
                writeSceneTable(out, scene, measurements);
        writeFrontierSteps(out, scene, rows, measurements);
    }
    writeNotMeasured(out, measurements);
    return out.str();
}

bool writeBenchReport(const std::string& directory,
        const std::vector<BenchMeasurement>& measurements, const BenchRunInfo& info,
        std::string& error) {
    std::error_code ec;
    fs::create_directories(directory, ec);
    if (ec) {
        error = directory + ": " + ec.message();
        return false;
    }
    const fs::path dir(directory);
    if (!writeFileAtomically(dir / "bench.csv", benchCsv(measurements), error)) return false;
    if (!writeFileAtomically(dir / "bench.md", benchMarkdown(measurements, info), error)) {
        fs::remove(dir / "bench.csv", ec);
        return false;
    }
    return true;
}

bool runPlotScript(const std::string& python, const std::string& script,
        const std::string& csvPath, const std::string& pngPath, std::string& message) {
    if (::access(python.c_str(), X_OK) != 0) {
        message = python + " not found";
        return false;
    }
    if (!fs::exists(script)) {
        message = script + " not found";
        return false;
    }
    int pipeFds[2];
    if (::pipe(pipeFds) != 0) {
        message = "cannot create a pipe";
        return false;
    }
    const pid_t pid = ::fork();
    if (pid < 0) {
        ::close(pipeFds[0]);
        ::close(pipeFds[1]);
        message = "cannot start " + python;
        return false;
    }
    if (pid == 0) {
        ::dup2(pipeFds[1], 1);
        ::dup2(pipeFds[1], 2);
        ::close(pipeFds[0]);
        ::close(pipeFds[1]);
        const int devNull = ::open("/dev/null", O_RDONLY);
        if (devNull >= 0) ::dup2(devNull, 0);
        const char* argv[] = {python.c_str(), script.c_str(), csvPath.c_str(), pngPath.c_str(),
                nullptr};
        ::execv(python.c_str(), const_cast<char* const*>(argv));
        ::_exit(127);
    }
    ::close(pipeFds[1]);
    std::string output;
    char buffer[4096];
    for (ssize_t n; (n = ::read(pipeFds[0], buffer, sizeof buffer)) > 0;) {
        output.append(buffer, std::size_t(n));
    }
    ::close(pipeFds[0]);
    int status = 0;
    ::waitpid(pid, &status, 0);
    if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return true;
    std::istringstream lines(output);
    std::string line, last;
    while (std::getline(lines, line)) {
        if (!line.empty()) last = line;
    }
    message = last.empty() ? python + " " + script + " failed" : last;
    return false;
}

bool writeFileAtomically(const fs::path& path, const std::string& text, std::string& error) {
    const fs::path temporary = path.string() + ".tmp";
    {
        std::ofstream out(temporary, std::ios::binary);
        out << text;
        if (!out.flush()) {
            error = temporary.string() + ": cannot write";
            std::error_code ignored;
            fs::remove(temporary, ignored);
            return false;
        }
    }
    std::error_code ec;
    fs::rename(temporary, path, ec);
    if (ec) {
        error = path.string() + ": " + ec.message();
        fs::remove(temporary, ec);
        return false;
    }
    return true;
}

} // namespace gi::bench
