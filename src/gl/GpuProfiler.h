// Per-pass GPU and CPU timing. A GpuScope brackets a pass with two GL_TIMESTAMP queries and a
// debug group named after the pass. Each pass keeps a ring of query pairs that is read only
// once GL_QUERY_RESULT_AVAILABLE is set, so the frame never waits on the GPU; results feed a
// 64-frame running average (overlay) and the full sample list (medians for --timings/bench).
// A scope nested in another is timed too; totals are per pass name, not exclusive. A pass
// that runs several times in one frame (e.g. once per light) yields one sample per frame:
// the sum of its runs.
//
// Mesa's llvmpipe answers GL_TIMESTAMP when a command is queued for its rasterizer threads,
// not when they finish, so its timer queries miss the fragment work (a 1280x720 pass reads
// faster than a 256x256 one). TimingMode::Finish measures such drivers instead: glFinish
// before and after each pass, wall-clock time between. Renderers choose it with
// timingModeFor(GL_RENDERER).
#pragma once

#include "gl/Handle.h"

#include <array>
#include <chrono>
#include <map>
#include <string>
#include <vector>

namespace gi::gl {

struct PassTiming {
    std::string name;
    double gpuMsAverage = 0.0;   // mean over the last (up to) 64 resolved frames
    double gpuMsMedian = 0.0;    // median over every resolved sample
    double cpuMsAverage = 0.0;   // CPU time spent issuing the pass, same window
    int samples = 0;             // resolved GPU samples
};

enum class TimingMode { Queries, Finish };

// Finish for Mesa's software rasterizers (llvmpipe, softpipe), Queries elsewhere.
[[nodiscard]] TimingMode timingModeFor(const std::string& glRenderer);
[[nodiscard]] TimingMode currentContextTimingMode();

class GpuProfiler {
public:
    static constexpr int kRingSize = 16;
    static constexpr int kAverageWindow = 64;

    explicit GpuProfiler(TimingMode mode = currentContextTimingMode()) : mMode(mode) {}
    TimingMode mode() const { return mMode; }
    GpuProfiler(const GpuProfiler&) = delete;
    GpuProfiler& operator=(const GpuProfiler&) = delete;

    // Marks the start of a frame; scopes of the same name within one frame are summed.
    void newFrame() { ++mFrame; }

    void begin(const std::string& name);
    void end(const std::string& name);

    // Collects every query whose result is available, without waiting.
    void collect();
    // Waits for every outstanding query (headless runs, tests and benches only).
    void flush();
    // Forgets all samples (e.g. after warm-up frames).
    void clearSamples();

    // Passes in first-use order.
    [[nodiscard]] std::vector<PassTiming> timings() const;

private:
    struct QueryPair {
        Query start, stop;
        bool pending = false;
        double cpuMs = 0.0;
        long frame = 0;
    };
    struct PassRecord {
        std::array<QueryPair, kRingSize> ring;
        int next = 0;
        std::chrono::steady_clock::time_point cpuStart;
        std::vector<double> gpuMs, cpuMs;
        long lastResolvedFrame = -1;
    };
    void resolve(PassRecord& record, QueryPair& pair, bool wait);
    void addSample(PassRecord& record, long frame, double gpuMs, double cpuMs);

    std::map<std::string, PassRecord> mPasses;
    std::vector<std::string> mOrder;
    long mFrame = 0;
    TimingMode mMode = TimingMode::Queries;
};

// RAII scope: times the enclosed GL commands as pass `name` and labels them as a debug group.
class GpuScope {
public:
    GpuScope(GpuProfiler& profiler, std::string name);
    ~GpuScope();
    GpuScope(const GpuScope&) = delete;
    GpuScope& operator=(const GpuScope&) = delete;

private:
    GpuProfiler& mProfiler;
    std::string mName;
};

} // namespace gi::gl
