#include "core/ToneMap.h"

#include "app/CommandLine.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace gi::core {
namespace {

TEST(ToneMap, ManualExposureIsExactlyTwoToTheEv) {
    Image image(2, 1);
    image.set(0, 0, {0.1f, 0.2f, 0.3f});
    image.set(1, 0, {0.01f, 0.02f, 0.03f});
    for (float ev : {-3.0f, -1.0f, 0.0f, 1.0f, 2.0f}) {
        const float exposure = exposureFor({false, ev, ToneCurve::None}, image, {});
        EXPECT_EQ(exposure, std::ldexp(1.0f, int(ev)));
        const Image mapped = applyToneMapping(image, exposure, ToneCurve::None);
        for (std::size_t i = 0; i < image.rgb.size(); ++i) {
            EXPECT_EQ(mapped.rgb[i], std::min(image.rgb[i] * exposure, 1.0f));
        }
    }
}

TEST(ToneMap, AutoExposureOfAConstantImageGivesMiddleGrey) {
    for (float value : {0.001f, 0.05f, 1.0f, 30.0f}) {
        Image image(8, 4);
        for (float& v : image.rgb) v = value;
        const float exposure = exposureFor({true, 0.0f, ToneCurve::None}, image, {});
        const Image mapped = applyToneMapping(image, exposure, ToneCurve::None);
        EXPECT_NEAR(luminance(mapped.at(3, 2)), kAutoExposureKey, 1e-5f) << value;
    }
}

TEST(ToneMap, AutoExposureMetersOnlyGeometry) {
    Image image(2, 1);
    image.set(0, 0, glm::vec3(0.5f));
    image.set(1, 0, glm::vec3(0.0f));   // the empty background
    const std::optional<float> average = logAverageLuminance(image, {1.0f, 0.0f});
    ASSERT_TRUE(average);
    EXPECT_NEAR(*average, 0.5f, 1e-6f);
    EXPECT_FALSE(logAverageLuminance(image, {0.0f, 0.0f}));
    // A black pixel of geometry (a shadow) does not pull the average down.
    EXPECT_NEAR(*logAverageLuminance(image, {1.0f, 1.0f}), 0.5f, 1e-6f);
    EXPECT_EQ(exposureFor({true, 0.0f, ToneCurve::None}, image, {0.0f, 0.0f}), 1.0f);
}

TEST(ToneMap, FilmicCurveIsMonotonicFromZeroToAtMostOne) {
    EXPECT_EQ(filmicCurve(0.0f), 0.0f);
    EXPECT_EQ(filmicCurve(-1.0f), 0.0f);
    float previous = 0.0f;
    for (float x = 1e-3f; x < 1e4f; x *= 1.1f) {
        const float y = filmicCurve(x);
        EXPECT_GE(y, previous) << x;
        EXPECT_LE(y, 1.0f) << x;
        previous = y;
    }
    EXPECT_GT(filmicCurve(1e4f), 0.99f);
    // Mid grey stays in the middle of the display range, not crushed or blown out.
    EXPECT_GT(filmicCurve(kAutoExposureKey), 0.15f);
    EXPECT_LT(filmicCurve(kAutoExposureKey), 0.35f);
}

TEST(ToneMap, ParsesCurveNames) {
    EXPECT_EQ(parseToneCurve("none"), ToneCurve::None);
    EXPECT_EQ(parseToneCurve("filmic"), ToneCurve::Filmic);
    EXPECT_FALSE(parseToneCurve("aces"));
    EXPECT_STREQ(toneCurveName(ToneCurve::Filmic), "filmic");
}

std::optional<app::Config> parse(std::vector<const char*> args, std::string& error) {
    args.insert(args.begin(), "voxatlas");
    return app::parseCommandLine(int(args.size()), args.data(), error);
}

TEST(ToneMapOptions, RenderDefaultsToLinearViewToTheViewersLook) {
    std::string error;
    const auto render = parse({"render", "s.gltf", "--out", "a.png"}, error);
    ASSERT_TRUE(render) << error;
    EXPECT_FALSE(render->toneMapping.autoExposure);
    EXPECT_EQ(render->toneMapping.ev, 0.0f);
    EXPECT_EQ(render->toneMapping.curve, ToneCurve::None);
    const auto view = parse({"view"}, error);
    ASSERT_TRUE(view) << error;
    EXPECT_TRUE(view->toneMapping.autoExposure);
    EXPECT_EQ(view->toneMapping.curve, ToneCurve::Filmic);
    const auto linearView = parse({"view", "--exposure", "0", "--tonemap", "none"}, error);
    ASSERT_TRUE(linearView) << error;
    EXPECT_FALSE(linearView->toneMapping.autoExposure);
    EXPECT_EQ(linearView->toneMapping.curve, ToneCurve::None);
}

TEST(ToneMapOptions, ParsesAndRefuses) {
    std::string error;
    const auto config = parse({"render", "s.gltf", "--out", "a.png", "--exposure", "-1.5",
                                      "--tonemap", "filmic"}, error);
    ASSERT_TRUE(config) << error;
    EXPECT_EQ(config->toneMapping.ev, -1.5f);
    EXPECT_EQ(config->toneMapping.curve, ToneCurve::Filmic);
    for (const char* bad : {"x", "99", "-21", "nan", ""}) {
        EXPECT_FALSE(parse({"render", "s.gltf", "--out", "a.png", "--exposure", bad}, error));
        EXPECT_NE(error.find("--exposure"), std::string::npos) << error;
    }
    EXPECT_FALSE(parse({"render", "s.gltf", "--out", "a.png", "--tonemap", "y"}, error));
    EXPECT_NE(error.find("--tonemap 'y'"), std::string::npos) << error;
    EXPECT_FALSE(parse({"bench", "--exposure", "1"}, error));
}

} // namespace
} // namespace gi::core
