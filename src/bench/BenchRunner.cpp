#include "bench/BenchRunner.h"

#include "gl/Limits.h"
#include "gl/ShaderLibrary.h"
#include "reference/ImageMetrics.h"
#include "reference/ProgressBar.h"
#include "reference/ReferenceCache.h"
#include "render/FrameRenderer.h"

#include <algorithm>
#include <cmath>

namespace gi::bench {
namespace {

double median(std::vector<double> values) {
    if (values.empty()) return 0.0;
    std::sort(values.begin(), values.end());
    const std::size_t mid = values.size() / 2;
    return values.size() % 2 ? values[mid] : 0.5 * (values[mid - 1] + values[mid]);
}

bool startsWith(const std::string& text, const std::string& prefix) {
    return text.rfind(prefix, 0) == 0;
}

// Passes and allocations of the GI techniques (the atlas' voxel visibility counts as atlas
// cost); the debug views are not part of a frame.
bool isGiName(const std::string& name) {
    return (startsWith(name, "voxel/") || startsWith(name, "atlas/") ||
                   startsWith(name, "vpl/")) &&
           name.find("debug_view") == std::string::npos;
}

std::string formatDuration(double seconds) {
    const long s = std::lround(std::max(0.0, seconds));
    char text[32];
    if (s >= 3600) std::snprintf(text, sizeof text, "%ldh%02ldm", s / 3600, (s / 60) % 60);
    else std::snprintf(text, sizeof text, "%ldm%02lds", s / 60, s % 60);
    return text;
}

// Effective values of the swept keys that belong to the configuration's technique.
std::map<std::string, std::string> effectiveSettings(const Settings& settings,
        const std::vector<std::string>& keys, render::GiMode mode) {
    const std::string prefix = std::string(render::giModeName(mode)) + ".";
    std::map<std::string, std::string> values;
    for (const SettingSpec& spec : settingSpecs()) {
        if (startsWith(spec.key, prefix) &&
                std::find(keys.begin(), keys.end(), spec.key) != keys.end()) {
            values[spec.key] = spec.get(settings);
        }
    }
    return values;
}

struct ScoredErrors {
    double relativeRmse = 0.0;
    double energyRatio = 0.0;
};

// Errors over several frames of a configuration: the root mean square of the per-frame
// relative RMSE (one frame of a stochastic technique, e.g. one atlas sample set, can be far
// luckier or unluckier than the next) and the mean energy ratio.
ScoredErrors scoreFrames(const std::vector<core::Image>& frames, const core::Image& reference,
        const std::vector<float>& coverage) {
    double squares = 0.0, energy = 0.0;
    for (const core::Image& image : frames) {
        const reference::ImageErrors e = reference::measureImageError(image, reference, coverage);
        squares += e.relativeRmse * e.relativeRmse;
        energy += e.energyRatio;
    }
    const double n = double(std::max<std::size_t>(frames.size(), 1));
    return {std::sqrt(squares / n), energy / n};
}

} // namespace

BenchProgress::BenchProgress(std::vector<PlannedRun> plan, std::FILE* out)
    : mPlan(std::move(plan)), mOut(out), mLast(std::chrono::steady_clock::now()) {}

double BenchProgress::secondsPerCost(const PlannedRun& run) const {
    double modeSeconds = 0.0, modeCost = 0.0, allSeconds = 0.0, allCost = 0.0;
    for (const auto& [key, spent] : mSpent) {
        if (key == std::make_pair(run.scene, run.mode) && spent.second > 0.0) {
            return spent.first / spent.second;
        }
        if (key.second == run.mode) {
            modeSeconds += spent.first;
            modeCost += spent.second;
        }
        allSeconds += spent.first;
        allCost += spent.second;
    }
    if (modeCost > 0.0) return modeSeconds / modeCost;
    return allCost > 0.0 ? allSeconds / allCost : 0.0;
}

void BenchProgress::report(const BenchMeasurement& m) {
    const auto now = std::chrono::steady_clock::now();
    const double seconds = std::chrono::duration<double>(now - mLast).count();
    mLast = now;
    if (mDone < mPlan.size()) {
        const PlannedRun& run = mPlan[mDone];
        auto& spent = mSpent[{run.scene, run.mode}];
        spent.first += seconds;
        spent.second += run.cost;
    }
    ++mDone;
    double eta = 0.0;
    for (std::size_t i = mDone; i < mPlan.size(); ++i) {
        eta += mPlan[i].cost * secondsPerCost(mPlan[i]);
    }
    const int total = int(mPlan.size());
    const int width = int(std::to_string(total).size());
    std::fprintf(mOut, "[%*d/%d] ETA %s  %s %s | %s: ", width, int(mDone), total,
            formatDuration(eta).c_str(), m.scene.c_str(), seriesName(m.configuration).c_str(),
            m.configuration.label.c_str());
    if (!m.available) {
        std::fprintf(mOut, "not measured (%s)\n", m.unavailableReason.c_str());
    } else {
        char ratio[32] = "";
        if (m.frameRatio > 0.0) std::snprintf(ratio, sizeof ratio, " (x%.2f base)", m.frameRatio);
        std::fprintf(mOut,
                "frame %.1f ms%s, GI %.1f ms, GI memory %.1f MiB; rel. RMSE indirect %.1f %%, "
                "final %.1f %%, indirect energy x%.3f\n",
                m.frameMs, ratio, m.giMs, double(m.giMemoryBytes) / (1024.0 * 1024.0),
                100.0 * m.relRmseIndirect, 100.0 * m.relRmseFinal, m.energyRatioIndirect);
    }
    std::fflush(mOut);
}

BenchRunner::BenchRunner(const Settings& base, RunOptions options)
    : mBase(base), mOptions(options) {}

reference::ReferenceResult BenchRunner::reference(const BenchScene& scene,
        std::string& error) const {
    const reference::ReferenceCache cache(reference::ReferenceCache::defaultDirectory());
    reference::CachedRenderStatus status;
    reference::ProgressBar bar("reference " + scene.name + " " + std::to_string(scene.size.x) +
            "x" + std::to_string(scene.size.y) + ", " + std::to_string(mBase.reference.spp) +
            " spp");
    reference::ReferenceResult result = reference::renderReferenceCached(*scene.scene,
            scene.camera, scene.size.x, scene.size.y, mBase.pathTracer(), cache, status, error,
            bar.callback());
    bar.finish();
    if (!status.storeError.empty()) {
        std::fprintf(stderr, "voxatlas bench: reference not cached: %s\n",
                status.storeError.c_str());
    }
    if (!result.final.empty()) {
        std::fprintf(stderr,
                "voxatlas bench: reference %s %s (noise %.2f %% indirect, %.2f %% final)\n",
                scene.name.c_str(),
                status.hit ? "loaded from the cache"
                           : ("rendered in " + std::to_string(result.seconds) + " s").c_str(),
                100.0 * result.noise.indirect, 100.0 * result.noise.final);
    }
    return result;
}

namespace {

// The images and times of one configuration's frames.
struct RenderedFrames {
    std::vector<double> frameMs;                  // wall time of each timed frame
    std::vector<gl::PassTiming> passes;           // per pass over the timed frames
    std::vector<core::Image> finalImages, indirectImages;   // the scored frames
};

// Warm-up, timed and scored frames of the configuration the renderer is set to.
RenderedFrames renderFrames(render::FrameRenderer& renderer, const BenchScene& scene,
        const BenchConfiguration& configuration, const RunOptions& options) {
    RenderedFrames out;
    gl::GpuProfiler profiler;
    auto frame = [&](render::OutputComponent output) {
        renderer.render(scene.camera, scene.size, output, profiler);
    };
    for (int i = 0; i < options.warmupFrames; ++i) frame(render::OutputComponent::Final);
    profiler.clearSamples();
    const int scored = std::max(1, options.scoredFrames);
    const bool progressive = configuration.accumulatedFrames > 1;
    for (int i = 0; i < options.timedFrames; ++i) {
        glFinish();
        const auto start = std::chrono::steady_clock::now();
        frame(render::OutputComponent::Final);
        glFinish();
        out.frameMs.push_back(std::chrono::duration<double, std::milli>(
                std::chrono::steady_clock::now() - start).count());
        profiler.collect();
        // Read back outside the timed window.
        if (!progressive && i >= options.timedFrames - scored) {
            out.finalImages.push_back(renderer.readback());
        }
    }
    profiler.flush();
    out.passes = profiler.timings();
    if (progressive) {
        // Scored after all of its frames; later frames no longer gather.
        const int rendered = options.warmupFrames + options.timedFrames;
        for (int i = rendered; i < configuration.accumulatedFrames; ++i) {
            frame(render::OutputComponent::Final);
        }
        for (int i = 0; i < scored; ++i) {
            frame(render::OutputComponent::Final);
            out.finalImages.push_back(renderer.readback());
        }
    }
    for (int i = 0; i < scored; ++i) {
        frame(render::OutputComponent::Indirect);
        out.indirectImages.push_back(renderer.readback());
    }
    return out;
}

// Frame time, GI pass time and memory of a measurement.
void recordCosts(const RenderedFrames& frames, const render::FrameRenderer& renderer,
        BenchMeasurement& m) {
    m.frameMs = median(frames.frameMs);
    for (const gl::PassTiming& pass : m.passes) {
        if (isGiName(pass.name)) m.giMs += pass.gpuMsMedian;
    }
    for (const gl::MemoryItem& item : renderer.memory()) {
        m.memoryBytes += item.bytes;
        if (isGiName(item.name)) m.giMemoryBytes += item.bytes;
    }
}

// The scored frames' errors against the ground truth.
void recordErrors(const RenderedFrames& frames, const reference::ReferenceResult& reference,
        BenchMeasurement& m) {
    const ScoredErrors indirect =
            scoreFrames(frames.indirectImages, reference.indirect, reference.coverage);
    const ScoredErrors final = scoreFrames(frames.finalImages, reference.final, reference.coverage);
    m.relRmseIndirect = indirect.relativeRmse;
    m.energyRatioIndirect = indirect.energyRatio;
    m.relRmseFinal = final.relativeRmse;
    m.scoredFrames = int(frames.indirectImages.size());
    if (!frames.indirectImages.empty()) m.indirectImage = frames.indirectImages.back();
}

} // namespace

bool BenchRunner::run(const BenchScene& scene, const reference::ReferenceResult& reference,
        BenchProgress& progress, std::vector<BenchMeasurement>& results, std::string& error) const {
    gl::ShaderLibrary shaders;
    render::FrameRenderer renderer;
    if (!renderer.init(*scene.scene, mBase, shaders, error)) return false;

    const std::vector<std::string> keys = changedKeys(scene.configurations);
    std::map<render::GiMode, double> baseFrameMs;

    for (const BenchConfiguration& configuration : scene.configurations) {
        BenchMeasurement m;
        m.scene = scene.name;
        m.configuration = configuration;
        m.size = scene.size;
        m.referenceNoiseIndirect = reference.noise.indirect;
        m.referenceNoiseFinal = reference.noise.final;
        m.referenceSpp = reference.spp;

        auto unavailable = [&](const std::string& why) {
            m.available = false;
            m.unavailableReason = why;
            progress.report(m);
            results.push_back(m);
        };
        Settings settings = mBase;
        std::string why;
        if (!applyConfiguration(configuration, settings, why)) {
            unavailable(why);
            continue;
        }
        m.settings = effectiveSettings(settings, keys, configuration.mode);

        // Every configuration starts from a new technique: no running average, accumulated
        // sample set or cached G-buffer carries over from the previous one.
        if (!renderer.setMode(render::GiMode::Direct, why) ||
                !renderer.setSettings(settings, why)) {
            unavailable(why);
            continue;
        }
        // Fails when the build has no such technique or it cannot honour these settings.
        if (!renderer.setMode(configuration.mode, why)) {
            unavailable(std::string(render::giModeName(configuration.mode)) + " unavailable: " +
                        why);
            continue;
        }

        const RenderedFrames frames = renderFrames(renderer, scene, configuration, mOptions);
        m.passes = frames.passes;
        if (const GLenum glError = glGetError(); glError != GL_NO_ERROR) {
            unavailable(gl::glErrorName(glError) + " while rendering");
            continue;
        }

        const bool wantsVoxelVisibility = m.settings.count("atlas.visibility") &&
                                          m.settings.at("atlas.visibility") == "voxel";
        const bool ranVoxelPass = std::any_of(m.passes.begin(), m.passes.end(),
                [](const gl::PassTiming& pass) { return startsWith(pass.name, "voxel/"); });
        if (configuration.mode == render::GiMode::Atlas && wantsVoxelVisibility && !ranVoxelPass) {
            unavailable("atlas.visibility=voxel: no voxel pass ran, the renderer gave the atlas "
                        "no occupancy volume (the image would equal visibility=none)");
            continue;
        }

        recordCosts(frames, renderer, m);
        recordErrors(frames, reference, m);
        if (configuration.base) baseFrameMs[configuration.mode] = m.frameMs;
        if (const auto base = baseFrameMs.find(configuration.mode); base != baseFrameMs.end()) {
            m.frameRatio = m.frameMs / base->second;
        }
        progress.report(m);
        results.push_back(m);
    }
    renderer.setMode(render::GiMode::Direct, error);
    return true;
}

} // namespace gi::bench
