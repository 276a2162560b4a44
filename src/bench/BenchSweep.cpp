#include "bench/BenchSweep.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace gi::bench {
namespace {

using render::GiMode;

std::string formatNumber(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", value);
    return text;
}

// Relative cost of a voxel frame: the cone trace dominates and scales with the traced pixels.
double voxelCost(double traceScale) {
    return 0.5 + 0.5 * (traceScale / 0.5) * (traceScale / 0.5);
}

// Relative cost of an atlas configuration: the gather scales with texels x samples, and the
// bench renders about six frames of it (one atlas base frame is about ten voxel base frames).
double atlasCost(int resolution, int samples, int frames) {
    const double texels = double(resolution) * resolution / (1024.0 * 1024.0);
    return 0.3 + 10.0 * texels * (samples / 100.0) * (frames / 6.0);
}

BenchConfiguration voxel(std::string label, std::vector<SettingChange> changes,
        double traceScale = 0.5, double costFactor = 1.0) {
    BenchConfiguration c;
    c.mode = GiMode::Voxel;
    c.label = std::move(label);
    c.changes = std::move(changes);
    c.costEstimate = voxelCost(traceScale) * costFactor;
    return c;
}

// A single-frame atlas configuration: progressive accumulation off, so the scored image is
// what one frame computes.
BenchConfiguration atlas(std::string label, int resolution, int samples,
        std::vector<SettingChange> extra = {}) {
    BenchConfiguration c;
    c.mode = GiMode::Atlas;
    c.label = std::move(label);
    c.changes = {{"atlas.progressive", "0"}};
    if (resolution != AtlasSettings{}.resolution) {
        c.changes.push_back({"atlas.resolution", std::to_string(resolution)});
    }
    if (samples != AtlasSettings{}.samples) {
        c.changes.push_back({"atlas.samples", std::to_string(samples)});
    }
    for (SettingChange& change : extra) c.changes.push_back(std::move(change));
    c.costEstimate = atlasCost(resolution, samples, 6);
    return c;
}

// Progressive accumulation: `samples` per frame for `frames` frames of a static scene, then
// scored (atlas.target_samples stops the gather after exactly that many sets).
BenchConfiguration progressive(int resolution, int samples, int frames) {
    BenchConfiguration c;
    c.mode = GiMode::Atlas;
    c.label = "progressive " + std::to_string(samples) + " x " + std::to_string(frames) + " frames";
    if (resolution != AtlasSettings{}.resolution) {
        c.label = "res " + std::to_string(resolution) + ", " + c.label;
    }
    c.changes = {{"atlas.progressive", "1"}, {"atlas.samples", std::to_string(samples)},
            {"atlas.target_samples", std::to_string(samples * frames)}};
    if (resolution != AtlasSettings{}.resolution) {
        c.changes.insert(c.changes.begin(), {"atlas.resolution", std::to_string(resolution)});
    }
    c.accumulatedFrames = frames;
    c.costEstimate = atlasCost(resolution, samples, frames);
    return c;
}

// Relative cost of a VPL frame: the gather dominates and scales with the VPLs each pixel
// visits; the voxel occupancy march makes each visit several times dearer.
double vplCost(int count, bool occluded) {
    return 0.3 + (occluded ? 1.5 : 0.3) * (double(count) / 1024.0);
}

BenchConfiguration vpl(std::string label, std::vector<SettingChange> changes) {
    BenchConfiguration c;
    c.mode = GiMode::Vpl;
    c.label = std::move(label);
    int count = VplSettings{}.count;
    bool occluded = VplSettings{}.visibility != VPL_VISIBILITY_NONE;
    for (const SettingChange& change : changes) {
        if (change.key == "vpl.count") count = std::stoi(change.value);
        if (change.key == "vpl.visibility") occluded = change.value != "none";
    }
    c.changes = std::move(changes);
    c.costEstimate = vplCost(count, occluded);
    return c;
}

// VPL count, clamp B and visibility one at a time around the defaults (1024 VPLs, B from the
// scene, cascade visibility), and every VPL at every pixel against the interleaved subsets.
void addVplSweep(std::vector<BenchConfiguration>& list, bool full) {
    BenchConfiguration base = vpl("base (1024, B auto, cascade)", {});
    base.base = true;
    list.push_back(base);
    for (const char* count : {"256", "512", "2048"}) {
        list.push_back(vpl(std::string("count ") + count, {{"vpl.count", count}}));
    }
    list.push_back(vpl("visibility none", {{"vpl.visibility", "none"}}));
    list.push_back(vpl("visibility svo", {{"vpl.visibility", "svo"}}));
    if (!full) return;
    // B in m^2: a millimetre-scale, a centimetre-scale and a decimetre-scale cut of 1/r^2.
    for (const char* clamp : {"1e-05", "0.0001", "0.01"}) {
        list.push_back(vpl(std::string("clamp ") + clamp + " m^2", {{"vpl.clamp", clamp}}));
    }
    list.push_back(vpl("count 256, visibility none",
            {{"vpl.count", "256"}, {"vpl.visibility", "none"}}));
    list.push_back(vpl("count 2048, visibility none",
            {{"vpl.count", "2048"}, {"vpl.visibility", "none"}}));
    list.push_back(vpl("every VPL per pixel", {{"vpl.interleave", "0"}}));
}

} // namespace

std::vector<SettingChange> voxelQualityPreset() {
    return {{"voxel.resolution", "64"}, {"voxel.trace_scale", "1"}, {"voxel.cones", "37"},
            {"voxel.jitter_elevation", "1"}, {"voxel.one_level_limit", "256"}};
}

float shortMaxDistance(float sceneDiagonal) {
    const double quarter = 0.25 * std::max(sceneDiagonal, 1e-6f);
    const double magnitude = std::pow(10.0, std::floor(std::log10(quarter)) - 1.0);
    return float(std::round(quarter / magnitude) * magnitude);
}

const char* sweepSizeName(SweepSize size) {
    switch (size) {
    case SweepSize::Smoke: return "smoke";
    case SweepSize::Quick: return "quick";
    case SweepSize::Full: return "full";
    }
    return "full";
}

std::optional<SweepSize> parseSweepSize(const std::string& name) {
    for (SweepSize size : {SweepSize::Smoke, SweepSize::Quick, SweepSize::Full}) {
        if (name == sweepSizeName(size)) return size;
    }
    return std::nullopt;
}

std::vector<BenchConfiguration> benchConfigurations(const SweepOptions& options) {
    const bool full = options.size == SweepSize::Full;
    const int progressiveFrames = std::max(16, options.minProgressiveFrames);
    std::vector<BenchConfiguration> list;

    // The no-GI baseline: what the GI modes' cost is relative to, and 100 % indirect error.
    BenchConfiguration direct;
    direct.mode = GiMode::Direct;
    direct.label = "direct light only";
    direct.base = true;
    direct.costEstimate = 0.3;

    BenchConfiguration voxelBase = voxel("base (v32 l3 trace 0.5 x8)", {});
    voxelBase.base = true;
    BenchConfiguration voxelFast = voxel("preset fast (v16 trace 0.25 x4)",
            {{"voxel.resolution", "16"}, {"voxel.trace_scale", "0.25"}, {"voxel.multiplier", "4"}},
            0.25, 0.8);
    BenchConfiguration atlasBase = atlas("base (1024^2, 100 samples)", 1024, 100);
    atlasBase.base = true;

    if (options.size == SweepSize::Smoke) {
        // 512^2 is the smallest atlas with room for Sponza's 17 k charts; few samples keep the
        // gather cheap.
        const int resolution = 512;
        BenchConfiguration atlasFew = atlas("res 512, 25 samples", resolution, 25);
        atlasFew.base = true;
        BenchConfiguration vplBase = vpl("base (1024, B auto, cascade)", {});
        vplBase.base = true;
        return {direct, voxelBase, voxelFast, atlasFew,
                progressive(resolution, 25, std::max(4, options.minProgressiveFrames)), vplBase,
                vpl("count 256, visibility none",
                        {{"vpl.count", "256"}, {"vpl.visibility", "none"}})};
    }

    const std::string shortDistance = formatNumber(options.shortDistance);
    list.push_back(direct);
    list.push_back(voxelBase);
    list.push_back(voxel("v=16", {{"voxel.resolution", "16"}}, 0.5, 0.8));
    list.push_back(voxel("v=64", {{"voxel.resolution", "64"}}, 0.5, 1.5));
    list.push_back(voxel("cascades 2", {{"voxel.cascades", "2"}}));
    list.push_back(voxel("cascades 4", {{"voxel.cascades", "4"}}, 0.5, 1.2));
    list.push_back(voxel("trace 1", {{"voxel.trace_scale", "1"}}, 1.0));
    list.push_back(voxel("trace 0.25", {{"voxel.trace_scale", "0.25"}}, 0.25));
    list.push_back(voxel("multiplier 4", {{"voxel.multiplier", "4"}}));
    list.push_back(voxel("max distance " + shortDistance + " m",
            {{"voxel.max_distance", shortDistance}}));
    list.push_back(voxel("scene-centred", {{"voxel.scene_centred", "1"}}));
    list.push_back(voxel("coverage mean (thesis)", {{"voxel.coverage_max_axis", "0"}}));
    list.push_back(voxel("inject 4v", {{"voxel.inject_resolution", "128"}}));
    list.push_back(voxel("fragment-mean inject", {{"voxel.inject_fragment_mean", "1"}}));
    list.push_back(voxelFast);
    list.push_back(voxel("preset balanced (trace 0.25 x4, max-axis)",
            {{"voxel.trace_scale", "0.25"}, {"voxel.multiplier", "4"},
                    {"voxel.coverage_max_axis", "1"}},
            0.25));
    // The sweep's fixed plan sets the levels the adaptive plan would size.
    std::vector<SettingChange> quality = voxelQualityPreset();
    // The fixed plan injects at v pixels unless told: 4v gives its finest voxel four.
    quality.insert(quality.begin() + 1, {"voxel.cascades", "4"});
    quality.push_back({"voxel.inject_resolution", "256"});
    quality.push_back({"voxel.coverage_max_axis", "1"});
    list.push_back(voxel(
            "preset quality (v64 l4 trace 1, max-axis, inject 4v, 37 cones)",
            quality, 1.0, 2.0));

    list.push_back(atlasBase);
    list.push_back(atlas("res 256", 256, 100));
    list.push_back(atlas("res 512", 512, 100));
    if (full) list.push_back(atlas("res 2048", 2048, 100));
    list.push_back(atlas("25 samples", 1024, 25));
    if (full) list.push_back(atlas("400 samples", 1024, 400));
    list.push_back(atlas("estimator merz2010", 1024, 100, {{"atlas.estimator", "merz2010"}}));
    list.push_back(atlas("voxel visibility", 1024, 100, {{"atlas.visibility", "voxel"}}));
    list.push_back(progressive(1024, 25, progressiveFrames));
    if (full) list.push_back(progressive(1024, 100, progressiveFrames));
    list.push_back(atlas("preset fast (512^2, 25 samples)", 512, 25));
    list.push_back(progressive(512, 25, progressiveFrames));
    addVplSweep(list, full);
    return list;
}

std::string seriesName(const BenchConfiguration& configuration) {
    std::string name = render::giModeName(configuration.mode);
    if (configuration.accumulatedFrames > 1) name += " progressive";
    return name;
}

std::vector<std::string> changedKeys(const std::vector<BenchConfiguration>& configurations) {
    std::vector<std::string> keys;
    for (const BenchConfiguration& c : configurations) {
        for (const SettingChange& change : c.changes) {
            if (std::find(keys.begin(), keys.end(), change.key) == keys.end()) {
                keys.push_back(change.key);
            }
        }
    }
    return keys;
}

std::string changesText(const BenchConfiguration& configuration) {
    std::string text;
    for (const SettingChange& change : configuration.changes) {
        text += (text.empty() ? "" : ";") + change.key + "=" + change.value;
    }
    return text;
}

bool applyConfiguration(const BenchConfiguration& configuration, Settings& settings,
        std::string& error) {
    for (const SettingChange& change : configuration.changes) {
        if (!applySetting(settings, change.key + "=" + change.value, error)) return false;
    }
    return true;
}

} // namespace gi::bench
