#include "bench/AccuracyReport.h"

#include "bench/AccuracyImages.h"
#include "bench/BenchReport.h"
#include "core/ToneMap.h"
#include "reference/ImageMetrics.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <sstream>

namespace gi::bench {
namespace {

namespace fs = std::filesystem;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// The reference's noise must stay under this share of the error it scores (DESIGN.md).
constexpr double kNoiseShareOfError = 0.2;

std::string number(double value, int decimals = 3) {
    if (!std::isfinite(value)) return "n/a";
    char text[32];
    std::snprintf(text, sizeof text, "%.*f", decimals, value);
    return text;
}

std::string percent(double value) {
    return std::isfinite(value) ? number(100.0 * value, 1) + " %" : "n/a";
}

const BenchMeasurement* find(const SuiteSceneResult& result, const std::string& configuration) {
    for (const BenchMeasurement& m : result.measurements) {
        if (m.configuration.label == configuration) return &m;
    }
    return nullptr;
}

const SuiteSceneResult* findKind(const std::vector<SuiteSceneResult>& results, SceneKind kind) {
    for (const SuiteSceneResult& r : results) {
        if (r.scene.kind == kind) return &r;
    }
    return nullptr;
}

std::optional<double> leakOf(const std::vector<SuiteSceneResult>& results,
        const SuiteSceneResult& dark, const std::string& configuration) {
    const SuiteSceneResult* lit = findKind(results, SceneKind::LeakLit);
    if (dark.scene.kind != SceneKind::LeakDark || !lit) return std::nullopt;
    const BenchMeasurement* litRow = find(*lit, configuration);
    const BenchMeasurement* darkRow = find(dark, configuration);
    if (!litRow || !darkRow || !litRow->available || !darkRow->available) return std::nullopt;
    const double litMean = meanGeometryLuminance(litRow->indirectImage, lit->reference.coverage);
    const double darkMean = meanGeometryLuminance(darkRow->indirectImage, dark.reference.coverage);
    return litMean > 0.0 ? darkMean / litMean : kNaN;
}

// The targets `score` misses, each as "what measured vs what wanted", with its relative
// RMSE normalised by the reference's RMS (`relRmse` = score.relRmseIndirect) or by its mean
// (score.relRmseIndirectPerMean); the other targets do not depend on it.
std::vector<std::string> missedTargets(const SuiteScore& score, double relRmse) {
    std::vector<std::string> misses;
    const SuiteTarget& t = score.target;
    if (t.maxRelRmseIndirect && !(relRmse <= *t.maxRelRmseIndirect)) {
        misses.push_back("rel. RMSE " + number(relRmse) + " > " +
                         number(*t.maxRelRmseIndirect, 2));
    }
    if (t.minEnergy && !(score.energyIndirect >= *t.minEnergy)) {
        misses.push_back("energy " + number(score.energyIndirect) + " < " +
                         number(*t.minEnergy, 2));
    }
    if (t.maxEnergy && !(score.energyIndirect <= *t.maxEnergy)) {
        misses.push_back("energy " + number(score.energyIndirect) + " > " +
                         number(*t.maxEnergy, 2));
    }
    if (t.maxIndirectRatioToNoGi &&
            !(score.indirectRatioToNoGi <= *t.maxIndirectRatioToNoGi)) {
        misses.push_back("rel. RMSE x" + number(score.indirectRatioToNoGi, 2) + " of no GI > x" +
                         number(*t.maxIndirectRatioToNoGi, 2));
    }
    if (t.maxLeak && !(score.leak && *score.leak <= *t.maxLeak)) {
        misses.push_back("leak " + (score.leak ? percent(*score.leak) : std::string("n/a")) +
                         " > " + percent(*t.maxLeak));
    }
    return misses;
}

std::string targetText(const SuiteTarget& t) {
    std::vector<std::string> parts;
    if (t.maxRelRmseIndirect) parts.push_back("rel. RMSE <= " + number(*t.maxRelRmseIndirect, 2));
    if (t.minEnergy && t.maxEnergy) {
        parts.push_back("energy " + number(*t.minEnergy, 2) + "-" + number(*t.maxEnergy, 2));
    }
    if (t.maxIndirectRatioToNoGi) {
        parts.push_back("rel. RMSE <= x" + number(*t.maxIndirectRatioToNoGi, 1) + " no GI");
    }
    if (t.maxLeak) parts.push_back("leak <= " + percent(*t.maxLeak));
    std::string text;
    for (const std::string& part : parts) text += (text.empty() ? "" : ", ") + part;
    return text;
}

const char* kindName(SceneKind kind) {
    switch (kind) {
    case SceneKind::Cornell: return "cornell";
    case SceneKind::Sponza: return "sponza";
    case SceneKind::LeakLit: return "leak-lit";
    case SceneKind::LeakDark: return "leak-dark";
    case SceneKind::Energy: return "energy";
    case SceneKind::Scored: return "scored";
    }
    return "scored";
}

std::vector<std::string> configurationNames() {
    return {kSuiteDirect, kSuiteVoxel, kSuiteVoxelQuality, kSuiteAtlas, kSuiteAtlasConverged,
            kSuiteVpl};
}

const SuiteScore* findScore(const std::vector<SuiteScore>& scores, const std::string& scene,
        const std::string& configuration) {
    for (const SuiteScore& s : scores) {
        if (s.scene == scene && s.configuration == configuration) return &s;
    }
    return nullptr;
}

// One table: a row per scene, a column per configuration, `cell` of each score.
template <typename Cell>
void gridTable(std::ostringstream& out, const std::vector<SuiteSceneResult>& results,
        const std::vector<SuiteScore>& scores, Cell cell) {
    out << "| scene |";
    for (const std::string& c : configurationNames()) out << " " << c << " |";
    out << "\n| --- |";
    for (std::size_t i = 0; i < configurationNames().size(); ++i) out << " ---: |";
    out << "\n";
    for (const SuiteSceneResult& r : results) {
        out << "| " << r.scene.name << " |";
        for (const std::string& c : configurationNames()) {
            const SuiteScore* s = findScore(scores, r.scene.name, c);
            out << " " << (!s ? "-" : !s->available ? "not run" : cell(*s)) << " |";
        }
        out << "\n";
    }
    out << "\n";
}

// The verdict on a score's targets: "met", "not run" or the misses.
std::string verdictOf(const SuiteScore& s, const std::vector<std::string>& misses) {
    if (!s.available) return "not run";
    std::string verdict = "met";
    for (std::size_t i = 0; i < misses.size(); ++i) {
        verdict = (i == 0 ? "**missed**: " : verdict + "; ") + misses[i];
    }
    return verdict;
}

void targetsSection(std::ostringstream& out, const std::vector<SuiteScore>& scores) {
    int met = 0, metPerMean = 0, total = 0;
    out << "## Targets\n\nRelative RMSE as everywhere on this page, sqrt(sum (a - b)^2 / sum "
           "b^2); the last column holds the targets to the RMSE over the reference's mean "
           "radiance instead, the normalisation the accuracy issue's own figures fit "
           "(`accuracy-analysis.md`, 'The targets' normalisation').\n\n"
           "| scene | configuration | target | measured | | rel. RMSE over the mean | |\n"
           "| --- | --- | --- | --- | --- | --- | --- |\n";
    for (const SuiteScore& s : scores) {
        if (!s.target.any()) continue;
        ++total;
        met += s.available && s.misses.empty();
        metPerMean += s.available && s.missesPerMean.empty();
        std::string measured = "rel. RMSE " + number(s.relRmseIndirect) + ", energy " +
                               number(s.energyIndirect);
        if (s.target.maxIndirectRatioToNoGi) {
            // The final image's ratio too: in Sponza's sun view it is the direct light's
            // (accuracy-analysis.md), not a target.
            measured += " (x" + number(s.indirectRatioToNoGi, 2) + " no GI; final image x" +
                        number(s.finalRatioToNoGi, 2) + ")";
        }
        if (s.leak) measured = "leak " + percent(*s.leak);
        const std::string perMean = !s.available || s.leak ? std::string("-")
                                                            : number(s.relRmseIndirectPerMean);
        out << "| " << s.scene << " | " << s.configuration << " | " << targetText(s.target)
            << " | " << (s.available ? measured : "-") << " | " << verdictOf(s, s.misses)
            << " | " << perMean << " | " << verdictOf(s, s.missesPerMean) << " |\n";
    }
    out << "\n" << met << " of " << total << " targets met (" << metPerMean << " of " << total
        << " with the relative RMSE over the reference's mean).\n\n";
}

void scenesSection(std::ostringstream& out, const std::vector<SuiteSceneResult>& results) {
    out << "## Scenes\n\n| scene | tests | camera, lights | pixels | reference |\n"
           "| --- | --- | --- | --- | --- |\n";
    for (const SuiteSceneResult& r : results) {
        std::string lights;
        for (const std::string& l : r.scene.lights) lights += " --light " + l;
        out << "| " << r.scene.name << " | " << r.scene.tests << " | `"
            << (r.scene.file.empty() ? "Sponza" : r.scene.file) << " --camera " << r.scene.camera
            << lights << "` | " << r.size.x << "x" << r.size.y << " | " << r.reference.spp
            << " spp, noise " << percent(r.reference.noise.indirect) << " |\n";
    }
    out << "\n";
}

} // namespace

double rmsOverMean(const core::Image& image, const std::vector<float>& coverage) {
    double sum = 0.0, squares = 0.0;
    std::size_t count = 0;
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            const std::size_t p = std::size_t(y) * std::size_t(image.width) + std::size_t(x);
            if (p < coverage.size() && coverage[p] <= reference::kGeometryCoverage) continue;
            const glm::vec3 c = image.at(x, y);
            for (int k = 0; k < 3; ++k) {
                sum += double(c[k]);
                squares += double(c[k]) * double(c[k]);
            }
            count += 3;
        }
    }
    return count && sum > 0.0 ? std::sqrt(squares / double(count)) / (sum / double(count)) : kNaN;
}

double meanGeometryLuminance(const core::Image& image, const std::vector<float>& coverage) {
    double sum = 0.0;
    std::size_t count = 0;
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            const std::size_t p = std::size_t(y) * std::size_t(image.width) + std::size_t(x);
            if (p < coverage.size() && coverage[p] <= reference::kGeometryCoverage) continue;
            sum += core::luminance(image.at(x, y));
            ++count;
        }
    }
    return count ? sum / double(count) : kNaN;
}

std::vector<SuiteScore> scoreSuite(const std::vector<SuiteSceneResult>& results) {
    std::vector<SuiteScore> scores;
    for (const SuiteSceneResult& r : results) {
        const BenchMeasurement* direct = find(r, kSuiteDirect);
        const double noGiFinal = direct && direct->available ? direct->relRmseFinal : kNaN;
        const double noGiIndirect =
                direct && direct->available ? direct->relRmseIndirect : kNaN;
        const double perMean = rmsOverMean(r.reference.indirect, r.reference.coverage);
        for (const BenchMeasurement& m : r.measurements) {
            SuiteScore s;
            s.scene = r.scene.name;
            s.configuration = m.configuration.label;
            s.kind = r.scene.kind;
            s.available = m.available;
            s.unavailableReason = m.unavailableReason;
            s.target = suiteTarget(r.scene.kind, s.configuration);
            if (m.available) {
                s.relRmseIndirect = m.relRmseIndirect;
                s.energyIndirect = m.energyRatioIndirect;
                s.relRmseFinal = m.relRmseFinal;
                s.finalRatioToNoGi = noGiFinal > 0.0 ? m.relRmseFinal / noGiFinal : kNaN;
                s.indirectRatioToNoGi =
                        noGiIndirect > 0.0 ? m.relRmseIndirect / noGiIndirect : kNaN;
                s.meanIndirect = meanGeometryLuminance(m.indirectImage, r.reference.coverage);
                s.leak = leakOf(results, r, s.configuration);
                s.noiseLimited = !(r.reference.noise.indirect <=
                                   kNoiseShareOfError * m.relRmseIndirect);
                s.frameMs = m.frameMs;
                s.relRmseIndirectPerMean = m.relRmseIndirect * perMean;
                s.misses = missedTargets(s, s.relRmseIndirect);
                s.missesPerMean = missedTargets(s, s.relRmseIndirectPerMean);
            }
            scores.push_back(s);
        }
    }
    return scores;
}

std::string accuracyCsv(const std::vector<SuiteScore>& scores) {
    std::ostringstream out;
    out << "scene,kind,configuration,available,rel_rmse_indirect,energy_indirect,"
           "rel_rmse_final,final_ratio_to_no_gi,mean_indirect,leak,noise_limited,frame_ms,"
           "target,misses,rel_rmse_indirect_per_mean,misses_per_mean\n";
    for (const SuiteScore& s : scores) {
        std::string misses, missesPerMean;
        for (const std::string& m : s.misses) misses += (misses.empty() ? "" : "; ") + m;
        for (const std::string& m : s.missesPerMean) {
            missesPerMean += (missesPerMean.empty() ? "" : "; ") + m;
        }
        out << s.scene << "," << kindName(s.kind) << "," << s.configuration << ","
            << (s.available ? 1 : 0) << "," << number(s.relRmseIndirect, 5) << ","
            << number(s.energyIndirect, 5) << "," << number(s.relRmseFinal, 5) << ","
            << number(s.finalRatioToNoGi, 5) << "," << number(s.meanIndirect, 6) << ","
            << (s.leak ? number(*s.leak, 5) : "") << "," << (s.noiseLimited ? 1 : 0) << ","
            << number(s.frameMs, 1) << ",\"" << targetText(s.target) << "\",\"" << misses
            << "\"," << number(s.relRmseIndirectPerMean, 5) << ",\"" << missesPerMean << "\"\n";
    }
    return out.str();
}

std::string accuracyMarkdown(const std::vector<SuiteSceneResult>& results,
        const std::vector<SuiteScore>& scores, const SuiteRunInfo& info) {
    std::ostringstream out;
    out << "# Accuracy on the scene suite\n\n"
        << "Every scene of `assets/scene_suite/` and two lightings of Sponza, rendered at the "
           "program's defaults "
        << (info.glossy ? "but with glossy materials (`material.model=gltf`: glTF's "
                          "metallic-roughness BRDF on the GPU and in the path tracer)"
                        : "(`material.specular=0`, so the images compare with the "
                          "Lambertian path tracer)")
        << " in every GI mode and scored against the one-bounce path "
           "tracer over the pixels it covers: the indirect component's relative RMSE and "
           "energy ratio, and the final image's error over that of the no-GI image.\n\n"
        << "Produced by `" << info.command << "` (" << info.size << " form) on " << info.date
        << ", " << info.glRenderer << ", in " << number(info.seconds / 60.0, 1)
        << " min; load average " << info.loadBefore << " before, " << info.loadAfter
        << " after.\n\n"
        << "Configurations: **direct** no GI; **voxel** the defaults; **voxel quality** "
           "v=64, full-resolution trace, 37 cones moved in elevation by the dither, one level "
           "of up to 256^3 voxels (`voxel.one_level_limit`); **atlas** the "
           "defaults, one frame; **atlas converged** "
           "`atlas.visibility=voxel`, accumulated to `atlas.target_samples`; **vpl** the "
           "defaults (`vpl.count` VPLs, cascade visibility, 4x4 interleaving).\n\n";
    for (const std::string& note : info.notes) out << "Note: " << note << "\n\n";
    out << "Why each missed target is missed, and what was tried: `accuracy-analysis.md`.\n\n";

    targetsSection(out, scores);
    // The dark room has no indirect light to be relative to: its score is the leak.
    auto scored = [](auto cell) {
        return [cell](const SuiteScore& s) {
            return s.kind == SceneKind::LeakDark ? std::string("(leak)") : cell(s);
        };
    };
    out << "## Relative RMSE of the indirect component\n\n"
           "(noise: marked * where the reference's noise exceeds a fifth of the error)\n\n";
    gridTable(out, results, scores, scored([](const SuiteScore& s) {
        return number(s.relRmseIndirect) + (s.noiseLimited ? "*" : "");
    }));
    out << "## Relative RMSE of the indirect component over the reference's mean\n\n"
           "RMSE / the reference's mean radiance: the figures above times the reference's "
           "RMS / mean over its pixels (the direct column's, an image of zeros).\n\n";
    gridTable(out, results, scores, scored([](const SuiteScore& s) {
        return number(s.relRmseIndirectPerMean);
    }));
    out << "## Indirect energy ratio (ours / reference)\n\n";
    gridTable(out, results, scores,
            scored([](const SuiteScore& s) { return number(s.energyIndirect); }));
    out << "## Final image: relative RMSE, and its ratio to the no-GI image's\n\n";
    gridTable(out, results, scores, scored([](const SuiteScore& s) {
        return number(s.relRmseFinal) + " (x" + number(s.finalRatioToNoGi, 2) + ")";
    }));
    if (const SuiteSceneResult* dark = findKind(results, SceneKind::LeakDark)) {
        const SuiteSceneResult* lit = findKind(results, SceneKind::LeakLit);
        if (lit) {
            const double truth =
                    meanGeometryLuminance(dark->reference.indirect, dark->reference.coverage) /
                    meanGeometryLuminance(lit->reference.indirect, lit->reference.coverage);
            out << "## Leak through the thin wall\n\nMean indirect luminance seen in the dark "
                   "room over that seen in the lit room (the path tracer: "
                << percent(truth) << ").\n\n";
            gridTable(out, {*dark}, scores, [](const SuiteScore& s) {
                return s.leak ? percent(*s.leak) : std::string("n/a");
            });
        }
    }
    scenesSection(out, results);
    out << "## Images\n\nIndirect light, each row: reference | voxel | atlas (converged where "
           "run) | vpl | voxel error | atlas error | vpl error. The four images share the reference's auto "
           "exposure and the filmic curve; the error maps are signed, in luminance: red where "
           "ours is brighter than the reference, blue where it is darker, black where they "
           "agree, at full strength where the difference reaches the reference's mean indirect "
           "luminance.\n\n";
    for (const SuiteSceneResult& r : results) {
        out << "### " << r.scene.name << "\n\n![" << r.scene.name << "](images/"
            << accuracyImageName(r.scene.name) << ")\n\n";
    }
    return out.str();
}

bool writeAccuracyReport(const std::string& directory,
        const std::vector<SuiteSceneResult>& results, const SuiteRunInfo& info,
        std::string& error) {
    const fs::path dir(directory);
    std::error_code ec;
    fs::create_directories(dir / "images", ec);
    if (ec) {
        error = (dir / "images").string() + ": " + ec.message();
        return false;
    }
    for (const SuiteSceneResult& r : results) {
        if (!writeAccuracyImage((dir / "images" / accuracyImageName(r.scene.name)).string(), r,
                    error)) {
            return false;
        }
    }
    const std::vector<SuiteScore> scores = scoreSuite(results);
    return writeFileAtomically(dir / "accuracy.csv", accuracyCsv(scores), error) &&
           writeFileAtomically(dir / "results-accuracy.md",
                   accuracyMarkdown(results, scores, info), error);
}

} // namespace gi::bench
