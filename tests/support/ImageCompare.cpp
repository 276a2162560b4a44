#include "ImageCompare.h"
#include "core/Colour.h"

#include "core/ImageIO.h"
#include "scene/Scene.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <sstream>

namespace gi::test {
namespace {

int encode8(float linear) { return int(std::lround(core::linearToSrgb(linear) * 255.0f)); }

std::string referencePath(const std::string& name) {
    return std::string(VOXATLAS_TEST_DATA_DIR) + "/references/" + name + ".png";
}

} // namespace

std::string testOutputDir() {
    const std::string dir = VOXATLAS_TEST_OUTPUT_DIR;
    std::filesystem::create_directories(dir);
    return dir;
}

ImageDifference compareImages(const core::Image& actual, const core::Image& expected,
        int pixelThreshold) {
    ImageDifference d;
    if (actual.width != expected.width || actual.height != expected.height) {
        d.sizeMismatch = true;
        return d;
    }
    const std::size_t pixels = std::size_t(actual.width) * std::size_t(actual.height);
    std::size_t failing = 0;
    double sum = 0.0, sumSquares = 0.0;
    for (std::size_t p = 0; p < pixels; ++p) {
        int pixelMax = 0;
        for (int c = 0; c < 3; ++c) {
            const int diff = std::abs(encode8(actual.rgb[p * 3 + std::size_t(c)]) -
                                      encode8(expected.rgb[p * 3 + std::size_t(c)]));
            pixelMax = std::max(pixelMax, diff);
            sum += diff;
            sumSquares += double(diff) * diff;
        }
        d.maxAbsDiff = std::max(d.maxAbsDiff, pixelMax);
        if (pixelMax > pixelThreshold) ++failing;
    }
    d.failingFraction = pixels ? double(failing) / double(pixels) : 0.0;
    d.meanAbsDiff = pixels ? sum / double(pixels * 3) : 0.0;
    d.rmse = pixels ? std::sqrt(sumSquares / double(pixels * 3)) : 0.0;
    return d;
}

void writeDiagnostics(const std::string& name, const core::Image& actual,
        const core::Image* expected) {
    const std::string base = testOutputDir() + "/" + name;
    std::filesystem::create_directories(std::filesystem::path(base).parent_path());
    std::string error;
    (void)core::writePng(base + ".actual.png", actual, error);
    if (!expected || expected->width != actual.width || expected->height != actual.height) return;
    (void)core::writePng(base + ".expected.png", *expected, error);
    core::Image diff(actual.width, actual.height);
    for (std::size_t i = 0; i < diff.rgb.size(); ++i) {
        // Differences amplified 8x in encoded space, shown as linear for the PNG writer.
        const float d = std::abs(core::linearToSrgb(actual.rgb[i]) - core::linearToSrgb(expected->rgb[i]));
        diff.rgb[i] = core::srgbToLinear(std::min(1.0f, d * 8.0f));
    }
    (void)core::writePng(base + ".diff.png", diff, error);
}

std::string compareWithReference(const core::Image& actual, const std::string& name,
        const ImageTolerance& tolerance) {
    const std::string path = referencePath(name);
    const char* update = std::getenv("VOXATLAS_UPDATE_REFERENCES");
    if (update && std::string(update) == "1") {
        std::filesystem::create_directories(std::filesystem::path(path).parent_path());
        std::string error;
        if (!core::writePng(path, actual, error)) return "cannot update reference: " + error;
        return "";
    }
    std::string lastMessage;
    for (const std::string& candidate : {path, referencePath(name + "_1")}) {
        if (!std::filesystem::exists(candidate)) continue;
        core::Image expected;
        std::string error;
        if (!core::readPng(candidate, expected, error)) return error;
        const ImageDifference d = compareImages(actual, expected, tolerance.pixelThreshold);
        std::ostringstream message;
        if (d.sizeMismatch) {
            message << name << ": size " << actual.width << "x" << actual.height
                    << " differs from the reference " << expected.width << "x" << expected.height;
        } else if (d.failingFraction <= tolerance.maxFailingFraction &&
                   d.meanAbsDiff <= tolerance.maxMeanAbsDiff) {
            return "";
        } else {
            message << name << ": maxAbsDiff " << d.maxAbsDiff << "/255, failing pixels "
                    << d.failingFraction * 100.0 << "% (allowed "
                    << tolerance.maxFailingFraction * 100.0 << "% over " << tolerance.pixelThreshold
                    << "/255), meanAbsDiff " << d.meanAbsDiff << "/255 (allowed "
                    << tolerance.maxMeanAbsDiff << ")";
        }
        writeDiagnostics(name, actual, &expected);
        lastMessage = message.str() + "; images in " + testOutputDir();
    }
    if (!lastMessage.empty()) return lastMessage;
    writeDiagnostics(name, actual, nullptr);
    return "no reference " + path + "; the candidate is " + testOutputDir() + "/" + name +
           ".actual.png (look at it, then VOXATLAS_UPDATE_REFERENCES=1 ctest -L gpu to accept)";
}

} // namespace gi::test
