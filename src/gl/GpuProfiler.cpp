#include "gl/GpuProfiler.h"

#include <algorithm>
#include <numeric>

namespace gi::gl {
namespace {

Query createTimestampQuery() {
    GLuint id = 0;
    glCreateQueries(GL_TIMESTAMP, 1, &id);
    return Query(id);
}

double median(std::vector<double> values) {
    if (values.empty()) return 0.0;
    const std::size_t mid = values.size() / 2;
    std::nth_element(values.begin(), values.begin() + mid, values.end());
    if (values.size() % 2) return values[mid];
    const double upper = values[mid];
    const double lower = *std::max_element(values.begin(), values.begin() + mid);
    return 0.5 * (lower + upper);
}

double tailMean(const std::vector<double>& values, int window) {
    if (values.empty()) return 0.0;
    const std::size_t n = std::min<std::size_t>(values.size(), std::size_t(window));
    return std::accumulate(values.end() - long(n), values.end(), 0.0) / double(n);
}

} // namespace

TimingMode timingModeFor(const std::string& glRenderer) {
    return glRenderer.find("llvmpipe") != std::string::npos ||
                           glRenderer.find("softpipe") != std::string::npos
            ? TimingMode::Finish
            : TimingMode::Queries;
}

TimingMode currentContextTimingMode() {
    const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    return timingModeFor(renderer ? renderer : "");
}

void GpuProfiler::addSample(PassRecord& record, long frame, double gpuMs, double cpuMs) {
    // Keep a bounded history so a long interactive session does not grow without limit.
    constexpr std::size_t kMaxSamples = 8192;
    if (record.gpuMs.size() >= kMaxSamples) {
        record.gpuMs.erase(record.gpuMs.begin(), record.gpuMs.begin() + kMaxSamples / 2);
        record.cpuMs.erase(record.cpuMs.begin(), record.cpuMs.begin() + kMaxSamples / 2);
    }
    if (frame == record.lastResolvedFrame && !record.gpuMs.empty()) {
        record.gpuMs.back() += gpuMs;
        record.cpuMs.back() += cpuMs;
    } else {
        record.gpuMs.push_back(gpuMs);
        record.cpuMs.push_back(cpuMs);
    }
    record.lastResolvedFrame = frame;
}

void GpuProfiler::resolve(PassRecord& record, QueryPair& pair, bool wait) {
    if (!pair.pending) return;
    GLint available = GL_FALSE;
    if (!wait) {
        glGetQueryObjectiv(pair.stop.id(), GL_QUERY_RESULT_AVAILABLE, &available);
        if (!available) return;
    }
    GLuint64 start = 0, stop = 0;
    glGetQueryObjectui64v(pair.start.id(), GL_QUERY_RESULT, &start);
    glGetQueryObjectui64v(pair.stop.id(), GL_QUERY_RESULT, &stop);
    addSample(record, pair.frame, double(stop - start) * 1e-6, pair.cpuMs);
    pair.pending = false;
}

void GpuProfiler::begin(const std::string& name) {
    auto [it, inserted] = mPasses.try_emplace(name);
    PassRecord& record = it->second;
    if (inserted) {
        mOrder.push_back(name);
        for (QueryPair& pair : record.ring) {
            pair.start = createTimestampQuery();
            pair.stop = createTimestampQuery();
        }
    }
    if (mMode == TimingMode::Finish) {
        glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 0, -1, name.c_str());
        glFinish();
        record.cpuStart = std::chrono::steady_clock::now();
        return;
    }
    QueryPair& pair = record.ring[std::size_t(record.next)];
    // The ring is full only if the GPU is more than kRingSize frames behind; waiting then
    // is the only way to keep the sample, and never happens at interactive rates.
    resolve(record, pair, true);
    glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 0, -1, name.c_str());
    glQueryCounter(pair.start.id(), GL_TIMESTAMP);
    record.cpuStart = std::chrono::steady_clock::now();
}

void GpuProfiler::end(const std::string& name) {
    PassRecord& record = mPasses.at(name);
    if (mMode == TimingMode::Finish) {
        glFinish();
        const double ms = std::chrono::duration<double, std::milli>(
                std::chrono::steady_clock::now() - record.cpuStart).count();
        glPopDebugGroup();
        addSample(record, mFrame, ms, ms);
        return;
    }
    QueryPair& pair = record.ring[std::size_t(record.next)];
    glQueryCounter(pair.stop.id(), GL_TIMESTAMP);
    glPopDebugGroup();
    pair.cpuMs = std::chrono::duration<double, std::milli>(
            std::chrono::steady_clock::now() - record.cpuStart).count();
    pair.pending = true;
    pair.frame = mFrame;
    record.next = (record.next + 1) % kRingSize;
}

void GpuProfiler::collect() {
    for (auto& [name, record] : mPasses) {
        // Oldest first, so samples stay in submission order.
        for (int i = 0; i < kRingSize; ++i) {
            resolve(record, record.ring[std::size_t((record.next + i) % kRingSize)], false);
        }
    }
}

void GpuProfiler::flush() {
    for (auto& [name, record] : mPasses) {
        for (int i = 0; i < kRingSize; ++i) {
            resolve(record, record.ring[std::size_t((record.next + i) % kRingSize)], true);
        }
    }
}

void GpuProfiler::clearSamples() {
    flush();
    for (auto& [name, record] : mPasses) {
        record.gpuMs.clear();
        record.cpuMs.clear();
        record.lastResolvedFrame = -1;
    }
}

std::vector<PassTiming> GpuProfiler::timings() const {
    std::vector<PassTiming> result;
    for (const std::string& name : mOrder) {
        const PassRecord& record = mPasses.at(name);
        result.push_back({name, tailMean(record.gpuMs, kAverageWindow), median(record.gpuMs),
                tailMean(record.cpuMs, kAverageWindow), int(record.gpuMs.size())});
    }
    return result;
}

GpuScope::GpuScope(GpuProfiler& profiler, std::string name)
    : mProfiler(profiler), mName(std::move(name)) {
    mProfiler.begin(mName);
}

GpuScope::~GpuScope() { mProfiler.end(mName); }

} // namespace gi::gl
