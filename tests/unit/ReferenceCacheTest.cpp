// Reference cache: a second request is a hit with bit-identical data; every input the image
// depends on changes the key; damaged entries (flipped bytes, truncation, missing or bad JSON)
// are re-rendered, never trusted. Also the progress reporting of long renders and requests
// without a meaningful image.
#include "ReferenceTestScenes.h"
#include "reference/ProgressBar.h"
#include "reference/ReferenceCache.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>

namespace gi::reference {
namespace {

namespace fs = std::filesystem;

fs::path freshCacheDir(const std::string& name) {
    const fs::path dir = fs::path(VOXATLAS_TEST_OUTPUT_DIR) / "reference-cache" / name;
    fs::remove_all(dir);
    return dir;   // created by the cache on its first store
}

scene::Scene smallScene() {
    scene::Scene scene;
    const int white = test::addMaterial(scene, glm::vec3(0.7f));
    test::addQuad(scene, {glm::vec3(-1, 0, 1), glm::vec3(1, 0, 1), glm::vec3(1, 0, -1),
                                 glm::vec3(-1, 0, -1)},
            white);
    test::addQuad(scene, {glm::vec3(-1, 0, -1), glm::vec3(1, 0, -1), glm::vec3(1, 2, -1),
                                 glm::vec3(-1, 2, -1)},
            white);
    scene::Light light;
    light.position = glm::vec3(0.2f, 1.0f, 0.3f);
    scene.lights.push_back(light);
    return scene;
}

struct Fixture {
    scene::Scene scene = smallScene();
    scene::CameraView camera = scene::cameraLookAt(glm::vec3(0, 1, 3), glm::vec3(0, 0.5f, 0),
            glm::radians(45.0f), 4.0f / 3.0f, scene.bounds);
    ReferenceSettings settings;
    Fixture() {
        settings.spp = 4;
        settings.bounces = 1;
    }
    std::string key() const { return referenceCacheKey(scene, camera, 16, 12, settings); }
    ReferenceResult render(const ReferenceCache& cache, CachedRenderStatus& status) const {
        std::string error;
        ReferenceResult result =
                renderReferenceCached(scene, camera, 16, 12, settings, cache, status, error);
        EXPECT_TRUE(error.empty()) << error;
        EXPECT_TRUE(status.storeError.empty()) << status.storeError;
        return result;
    }
};

void expectIdentical(const ReferenceResult& a, const ReferenceResult& b) {
    for (const auto member : {&ReferenceResult::direct, &ReferenceResult::indirect,
                 &ReferenceResult::final}) {
        ASSERT_EQ((a.*member).width, (b.*member).width);
        ASSERT_EQ((a.*member).height, (b.*member).height);
        EXPECT_EQ(std::memcmp((a.*member).rgb.data(), (b.*member).rgb.data(),
                          (a.*member).rgb.size() * sizeof(float)),
                0);
    }
    EXPECT_EQ(a.coverage, b.coverage);
    EXPECT_EQ(a.spp, b.spp);
    EXPECT_EQ(a.bounces, b.bounces);
    EXPECT_EQ(a.rays.total(), b.rays.total());
    EXPECT_EQ(a.noise.final, b.noise.final);
    EXPECT_EQ(a.noise.indirect, b.noise.indirect);
}

TEST(ReferenceCache, SecondRequestIsAHitWithIdenticalData) {
    const Fixture f;
    const ReferenceCache cache(freshCacheDir("hit"));
    CachedRenderStatus status;
    const ReferenceResult first = f.render(cache, status);
    EXPECT_FALSE(status.hit);
    EXPECT_TRUE(fs::exists(cache.directory() / (f.key() + ".json")));
    const ReferenceResult second = f.render(cache, status);
    EXPECT_TRUE(status.hit);
    expectIdentical(first, second);
    EXPECT_DOUBLE_EQ(first.seconds, second.seconds) << "the stored render time is reported";
}

TEST(ReferenceCache, KeyCoversEveryInput) {
    const Fixture base;
    const std::string key = base.key();
    EXPECT_EQ(key.size(), 32u);
    EXPECT_EQ(key, Fixture().key()) << "equal inputs, equal key";
    auto differs = [&](auto change) {
        Fixture f;
        change(f);
        return f.key() != key;
    };
    EXPECT_TRUE(differs([](Fixture& f) { f.settings.spp = 8; }));
    EXPECT_TRUE(differs([](Fixture& f) { f.settings.bounces = 2; }));
    EXPECT_TRUE(differs([](Fixture& f) { f.settings.seed = 2; }));
    EXPECT_TRUE(differs([](Fixture& f) { f.settings.pixel = kReferencePixelCentre; }));
    EXPECT_FALSE(differs([](Fixture& f) { f.settings.threads = 1; }))
            << "the image does not depend on the thread count";
    EXPECT_TRUE(differs([](Fixture& f) { f.scene.lights[0].intensity = 2.0f; }));
    EXPECT_TRUE(differs([](Fixture& f) { f.scene.lights.push_back(scene::Light{}); }));
    scene::Light area;
    area.type = scene::LightType::Area;
    area.emitters.push_back({glm::vec3(0.0f), glm::vec3(1, 0, 0), glm::vec3(0, 0, 1)});
    EXPECT_TRUE(differs([&](Fixture& f) { f.scene.lights.push_back(area); }));
    area.emitters[0].radiance = glm::vec3(1.0f);
    const auto withArea = [&](Fixture& f) { f.scene.lights.push_back(area); };
    Fixture emitting;
    withArea(emitting);
    auto differsFromArea = [&](auto change) {
        Fixture f;
        withArea(f);
        change(f.scene.lights.back());
        return f.key() != emitting.key();
    };
    EXPECT_TRUE(differsFromArea([](scene::Light& l) { l.emitters[0].p2.x += 1e-6f; }));
    EXPECT_TRUE(differsFromArea([](scene::Light& l) { l.emitters[0].radiance.b = 2.0f; }));
    EXPECT_TRUE(differsFromArea([](scene::Light& l) { l.emitters[0].twoSided = true; }));
    EXPECT_TRUE(differsFromArea([](scene::Light& l) { l.emitters[0].instance = 0; }));
    EXPECT_TRUE(differsFromArea([](scene::Light& l) { l.type = scene::LightType::Sky; }));
    EXPECT_TRUE(differs([](Fixture& f) { f.scene.materials[0].baseColorFactor.g = 0.5f; }));
    EXPECT_TRUE(differs([](Fixture& f) { f.scene.primitives[0].positions[0].x += 1e-6f; }));
    EXPECT_TRUE(differs([](Fixture& f) { f.camera.view[3][0] += 0.01f; }));
    EXPECT_TRUE(differs([](Fixture& f) { f.camera.projection[0][0] *= 1.01f; }));
    const ReferenceSettings s = base.settings;
    EXPECT_NE(referenceCacheKey(base.scene, base.camera, 16, 13, s), key);
    EXPECT_NE(referenceCacheKey(base.scene, base.camera, 17, 12, s), key);
}

// Damages one file of a stored entry, then expects a miss that re-renders the same image and
// repairs the entry.
template <class Damage> void expectDamageIsIgnored(const std::string& name, Damage damage) {
    const Fixture f;
    const ReferenceCache cache(freshCacheDir(name));
    CachedRenderStatus status;
    const ReferenceResult original = f.render(cache, status);
    ASSERT_FALSE(status.hit);
    damage(cache.directory(), f.key());
    ReferenceResult out;
    EXPECT_FALSE(cache.load(f.key(), out));
    const ReferenceResult again = f.render(cache, status);
    EXPECT_FALSE(status.hit) << name << ": a damaged entry must be re-rendered";
    expectIdentical(original, again);
    EXPECT_TRUE(cache.load(f.key(), out)) << name << ": the re-render repairs the entry";
}

void flipByte(const fs::path& path, std::uintmax_t offsetFromEnd) {
    std::fstream file(path, std::ios::binary | std::ios::in | std::ios::out);
    const auto size = fs::file_size(path);
    file.seekg(std::streamoff(size - offsetFromEnd));
    char c = 0;
    file.get(c);
    file.seekp(std::streamoff(size - offsetFromEnd));
    file.put(char(c ^ 0x20));
}

TEST(ReferenceCache, FlippedPixelByteIsDetected) {
    expectDamageIsIgnored("flipped", [](const fs::path& dir, const std::string& key) {
        flipByte(dir / (key + ".final.pfm"), 7);
    });
}

TEST(ReferenceCache, TruncatedImageIsDetected) {
    expectDamageIsIgnored("truncated", [](const fs::path& dir, const std::string& key) {
        const fs::path path = dir / (key + ".indirect.pfm");
        fs::resize_file(path, fs::file_size(path) / 2);
    });
}

TEST(ReferenceCache, CorruptCoverageIsDetected) {
    expectDamageIsIgnored("coverage", [](const fs::path& dir, const std::string& key) {
        flipByte(dir / (key + ".coverage.pfm"), 2);
    });
}

TEST(ReferenceCache, MissingOrBadJsonIsDetected) {
    expectDamageIsIgnored("nojson", [](const fs::path& dir, const std::string& key) {
        fs::remove(dir / (key + ".json"));
    });
    expectDamageIsIgnored("badjson", [](const fs::path& dir, const std::string& key) {
        std::ofstream(dir / (key + ".json"), std::ios::trunc) << "{\"format\": 1, \"key\": ";
    });
    expectDamageIsIgnored("otherkey", [](const fs::path& dir, const std::string& key) {
        const fs::path path = dir / (key + ".json");
        std::ifstream in(path);
        std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        in.close();
        text.replace(text.find(key), 4, "ffff");
        std::ofstream(path, std::ios::trunc) << text;
    });
}

TEST(ReferenceCache, DefaultDirectoryFollowsEnvironment) {
    const char* saved = std::getenv("VOXATLAS_CACHE_DIR");
    const std::string savedValue = saved ? saved : "";
    ::setenv("VOXATLAS_CACHE_DIR", "/some/where", 1);
    EXPECT_EQ(ReferenceCache::defaultDirectory(), fs::path("/some/where"));
    ::unsetenv("VOXATLAS_CACHE_DIR");
    const char* xdg = std::getenv("XDG_CACHE_HOME");
    if (xdg && *xdg) {
        EXPECT_EQ(ReferenceCache::defaultDirectory(), fs::path(xdg) / "voxatlas" / "reference");
    } else if (const char* home = std::getenv("HOME"); home && *home) {
        EXPECT_EQ(ReferenceCache::defaultDirectory(),
                fs::path(home) / ".cache" / "voxatlas" / "reference");
    }
    if (saved) ::setenv("VOXATLAS_CACHE_DIR", savedValue.c_str(), 1);
}

TEST(ReferenceRenderer, ReportsProgressUpToOne) {
    const Fixture f;
    std::vector<double> fractions;
    const ReferenceResult result = renderReference(f.scene, f.camera, 40, 30, f.settings,
            [&](double fraction) { fractions.push_back(fraction); });
    ASSERT_FALSE(fractions.empty());
    EXPECT_TRUE(std::is_sorted(fractions.begin(), fractions.end()));
    EXPECT_GT(fractions.size(), 2u) << "one call per finished 16 x 16 tile";
    EXPECT_DOUBLE_EQ(fractions.back(), 1.0);
    EXPECT_EQ(std::count(fractions.begin(), fractions.end(), 1.0), 1);
    EXPECT_EQ(result.width(), 40);
}

// reference.pixel=centre sends every path through the pixel's centre: each pixel is wholly
// quad or wholly background (the area form has pixels straddling the quads' outline), and a
// point light's direct light at that one point is the same in both halves of the paths, so
// its noise estimate is exactly zero.
TEST(ReferenceRenderer, PixelCentrePathsAllLeaveThroughTheCentre) {
    Fixture area;
    area.settings.spp = 16;
    Fixture centre = area;
    centre.settings.pixel = kReferencePixelCentre;
    const ReferenceResult a = renderReference(area.scene, area.camera, 40, 30, area.settings);
    const ReferenceResult c =
            renderReference(centre.scene, centre.camera, 40, 30, centre.settings);
    const auto partial = [](const ReferenceResult& r) {
        return std::count_if(r.coverage.begin(), r.coverage.end(),
                [](float v) { return v > 0.0f && v < 1.0f; });
    };
    EXPECT_GT(partial(a), 10) << "the quads' outline crosses pixels";
    EXPECT_EQ(partial(c), 0);
    EXPECT_GT(std::count(c.coverage.begin(), c.coverage.end(), 1.0f), 200);
    EXPECT_GT(a.noise.direct, 0.0);
    EXPECT_EQ(c.noise.direct, 0.0);
}

TEST(ReferenceRenderer, DegenerateRequests) {
    const Fixture f;
    EXPECT_TRUE(renderReference(f.scene, f.camera, 0, 10, f.settings).final.empty());
    EXPECT_TRUE(renderReference(f.scene, f.camera, 10, -1, f.settings).final.empty());
    ReferenceSettings one = f.settings;
    one.spp = 1;
    const ReferenceResult single = renderReference(f.scene, f.camera, 8, 6, one);
    EXPECT_TRUE(std::isnan(single.noise.final)) << "no second half to compare with";
    EXPECT_TRUE(core::allFinite(single.final));
    const scene::Scene empty;
    const ReferenceResult nothing = renderReference(empty, f.camera, 8, 6, f.settings);
    ASSERT_EQ(nothing.width(), 8);
    EXPECT_EQ(nothing.final.rgb, std::vector<float>(8 * 6 * 3, 0.0f));
    EXPECT_EQ(nothing.coverage, std::vector<float>(8 * 6, 0.0f));
    EXPECT_TRUE(std::isnan(nothing.noise.final)) << "no geometry pixels";
    EXPECT_EQ(nothing.rays.primary, 8u * 6u * 4u);

    // Lights without a direction or with non-finite numbers light nothing and never make NaNs.
    Fixture hostile;
    scene::Light spot;
    spot.type = scene::LightType::Spot;
    spot.direction = glm::vec3(0.0f);
    scene::Light sun;
    sun.type = scene::LightType::Directional;
    sun.direction = glm::vec3(std::numeric_limits<float>::quiet_NaN());
    scene::Light bad;
    bad.position = glm::vec3(std::numeric_limits<float>::infinity());
    hostile.scene.lights = {spot, sun, bad};
    const ReferenceResult dark = renderReference(hostile.scene, hostile.camera, 8, 6, f.settings);
    EXPECT_EQ(dark.final.rgb, std::vector<float>(8 * 6 * 3, 0.0f));
}

std::string progressOutput(ProgressBar::Style style, const std::vector<double>& fractions) {
    std::FILE* out = std::tmpfile();
    {
        ProgressBar bar("ref", out, style);
        const ProgressCallback callback = bar.callback();
        for (double f : fractions) callback(f);
    }
    std::rewind(out);
    std::string text;
    for (int c = std::fgetc(out); c != EOF; c = std::fgetc(out)) text += char(c);
    std::fclose(out);
    return text;
}

TEST(ProgressBar, LinesModePrintsEveryTenPercentOnce) {
    const std::string text =
            progressOutput(ProgressBar::Style::Lines, {0.05, 0.12, 0.13, 0.5, 0.95, 1.0, 1.0});
    EXPECT_EQ(text.find('\r'), std::string::npos);
    // Each line shows the fraction that crossed the 10 % step.
    EXPECT_NE(text.find("ref:  12%  ETA"), std::string::npos) << text;
    EXPECT_NE(text.find("ref:  50%  ETA"), std::string::npos) << text;
    EXPECT_NE(text.find("ref:  95%  ETA"), std::string::npos) << text;
    EXPECT_NE(text.find("ref: 100%  done in"), std::string::npos) << text;
    EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 4) << text;
}

TEST(ProgressBar, TerminalModeRedrawsInPlaceAndEndsTheLine) {
    const std::string text = progressOutput(ProgressBar::Style::Terminal, {0.0, 0.5, 1.0});
    EXPECT_EQ(text.front(), '\r');
    EXPECT_NE(text.find("100%"), std::string::npos) << text;
    EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 1) << text;
    EXPECT_EQ(text.back(), '\n');
}

} // namespace
} // namespace gi::reference
