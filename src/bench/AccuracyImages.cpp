#include "bench/AccuracyImages.h"

#include "core/ImageIO.h"
#include "core/ToneMap.h"

#include <algorithm>
#include <cmath>

namespace gi::bench {
namespace {

constexpr int kGap = 2;   // pixels between panels
const glm::vec3 kGapColour{1.0f};

const BenchMeasurement* panelSource(const SuiteSceneResult& result,
        std::initializer_list<const char*> preferred) {
    for (const char* name : preferred) {
        for (const BenchMeasurement& m : result.measurements) {
            if (m.configuration.label == name && m.available && !m.indirectImage.empty()) {
                return &m;
            }
        }
    }
    return nullptr;
}

// The exposure of the reference's indirect light; a scene without any (the dark room) takes
// the exposure of the first render that has some, so a leak shows as the light it is.
float stripExposure(const SuiteSceneResult& result,
        std::initializer_list<const BenchMeasurement*> renders) {
    const std::vector<float>& coverage = result.reference.coverage;
    if (auto average = core::logAverageLuminance(result.reference.indirect, coverage)) {
        return core::autoExposure(*average);
    }
    for (const BenchMeasurement* m : renders) {
        if (!m) continue;
        if (auto average = core::logAverageLuminance(m->indirectImage, coverage)) {
            return core::autoExposure(*average);
        }
    }
    return 1.0f;
}

core::Image errorMap(const core::Image& image, const core::Image& truth, float scale) {
    core::Image out(truth.width, truth.height);
    if (image.width != truth.width || image.height != truth.height) return out;
    for (int y = 0; y < truth.height; ++y) {
        for (int x = 0; x < truth.width; ++x) {
            const float difference = core::luminance(image.at(x, y)) - core::luminance(truth.at(x, y));
            out.set(x, y, signedErrorColour(difference, scale));
        }
    }
    return out;
}

void paste(core::Image& strip, const core::Image& panel, int index) {
    const int left = index * (panel.width + kGap);
    for (int y = 0; y < panel.height; ++y) {
        for (int x = 0; x < panel.width; ++x) strip.set(left + x, y, panel.at(x, y));
    }
}

} // namespace

std::string accuracyImageName(const std::string& scene) { return "accuracy_" + scene + ".png"; }

glm::vec3 signedErrorColour(float difference, float scale) {
    if (!(scale > 0.0f) || !std::isfinite(difference)) return glm::vec3(0.0f);
    const float t = std::min(std::abs(difference) / scale, 1.0f);
    // A touch of green keeps small errors visible on a dark screen without mixing the sides.
    return difference > 0.0f ? glm::vec3(t, 0.25f * t, 0.0f) : glm::vec3(0.0f, 0.25f * t, t);
}

bool writeAccuracyImage(const std::string& path, const SuiteSceneResult& result,
        std::string& error) {
    const core::Image& truth = result.reference.indirect;
    const BenchMeasurement* voxel = panelSource(result, {kSuiteVoxel});
    const BenchMeasurement* atlas = panelSource(result, {kSuiteAtlasConverged, kSuiteAtlas});
    const BenchMeasurement* vpl = panelSource(result, {kSuiteVpl});
    const float exposure = stripExposure(result, {voxel, atlas, vpl});
    double mean = meanGeometryLuminance(truth, result.reference.coverage);
    if (!(mean > 0.0) && voxel) {
        mean = meanGeometryLuminance(voxel->indirectImage, result.reference.coverage);
    }
    const float scale = std::isfinite(mean) ? float(mean) : 0.0f;

    const core::Image blank(truth.width, truth.height);
    auto shown = [&](const BenchMeasurement* m) {
        return core::applyToneMapping(m ? m->indirectImage : blank, exposure,
                core::ToneCurve::Filmic);
    };
    const core::Image panels[] = {
            core::applyToneMapping(truth, exposure, core::ToneCurve::Filmic),
            shown(voxel),
            shown(atlas),
            shown(vpl),
            voxel ? errorMap(voxel->indirectImage, truth, scale) : blank,
            atlas ? errorMap(atlas->indirectImage, truth, scale) : blank,
            vpl ? errorMap(vpl->indirectImage, truth, scale) : blank,
    };
    const int count = int(std::size(panels));
    core::Image strip(count * truth.width + (count - 1) * kGap, truth.height);
    for (int y = 0; y < strip.height; ++y) {
        for (int x = 0; x < strip.width; ++x) strip.set(x, y, kGapColour);
    }
    for (int i = 0; i < count; ++i) paste(strip, panels[i], i);
    return core::writePng(path, strip, error);
}

} // namespace gi::bench
