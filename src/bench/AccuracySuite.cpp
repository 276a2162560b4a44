#include "bench/AccuracySuite.h"

#include "core/Settings.h"

#include <algorithm>

namespace gi::bench {
namespace {

using render::GiMode;

constexpr int kQuickTargetSamples = 400;

// The Sponza lightings of assets/scene_suite/README.md.
constexpr const char* kSponzaSunCamera = "-1.2,1.7,-8,0.8,3.5,10,60";
constexpr const char* kSponzaSunLight = "dir:0.2,-1,0.3:1,1,1:4";
constexpr const char* kSponzaArcadeCamera = "4.6,1.7,-9.5,4.3,2.2,10,60";
constexpr const char* kSponzaArcadeLight = "point:4.6,3.2,-3:1,1,1:5";

// A scene of assets/scene_suite/; `name` is the file's stem unless given.
SuiteScene suiteFile(const std::string& stem, SceneKind kind, std::string camera,
        std::string tests, std::string name = "") {
    SuiteScene scene;
    scene.file = "assets/scene_suite/" + stem + ".gltf";
    scene.name = name.empty() ? stem : std::move(name);
    scene.kind = kind;
    scene.camera = std::move(camera);
    scene.tests = std::move(tests);
    return scene;
}

SuiteScene sponza(std::string name, SceneKind kind, std::string camera, std::string light,
        std::string tests) {
    SuiteScene scene;
    scene.name = std::move(name);
    scene.kind = kind;
    scene.camera = std::move(camera);
    scene.lights = {"none", std::move(light)};
    scene.tests = std::move(tests);
    return scene;
}

BenchConfiguration configuration(GiMode mode, const char* name,
        std::vector<SettingChange> changes, double cost) {
    BenchConfiguration c;
    c.mode = mode;
    c.label = name;
    c.changes = std::move(changes);
    c.costEstimate = cost;
    return c;
}

bool isCornell(SceneKind kind) { return kind == SceneKind::Cornell; }

} // namespace

const char* suiteSizeName(SuiteSize size) {
    return size == SuiteSize::Quick ? "quick" : "full";
}

std::optional<SuiteSize> parseSuiteSize(const std::string& name) {
    if (name == "quick") return SuiteSize::Quick;
    if (name == "full") return SuiteSize::Full;
    return std::nullopt;
}

const std::vector<SuiteScene>& suiteScenes() {
    static const std::vector<SuiteScene> scenes = {
            suiteFile("cornell_classic", SceneKind::Cornell, "0",
                    "the Cornell box, point light 1 cm under the ceiling"),
            suiteFile("cornell_double_sided", SceneKind::Cornell, "0",
                    "the same, every material doubleSided with TEXCOORD_0"),
            suiteFile("cornell_low_light", SceneKind::Cornell, "0",
                    "the light 10 % of the height under the ceiling"),
            suiteFile("cornell_x10", SceneKind::Cornell, "0", "the box ten times larger"),
            suiteFile("cornell_spot", SceneKind::Cornell, "0", "one spot light pointing down"),
            suiteFile("cornell_open_front_sun", SceneKind::Cornell, "0",
                    "front open to a sun outside"),
            suiteFile("two_rooms_thin_wall", SceneKind::LeakLit, "0",
                    "two rooms, one finest voxel of wall between them: the lit room",
                    "two_rooms_lit"),
            suiteFile("two_rooms_thin_wall", SceneKind::LeakDark, "1",
                    "the dark room: every bit of its indirect light is a leak",
                    "two_rooms_dark"),
            suiteFile("closed_white_box", SceneKind::Energy, "0",
                    "a closed white box: energy balance"),
            sponza("sponza_sun", SceneKind::Sponza, kSponzaSunCamera, kSponzaSunLight,
                    "Sponza, a sun through the roof opening, camera in the court"),
            sponza("sponza_arcade", SceneKind::Scored, kSponzaArcadeCamera, kSponzaArcadeLight,
                    "Sponza, a point light in a side arcade"),
    };
    return scenes;
}

bool isSponzaScene(const SuiteScene& scene) { return scene.file.empty(); }

glm::ivec2 suiteImageSize(SuiteSize size, const SuiteScene& scene) {
    const bool quick = size == SuiteSize::Quick;
    if (isSponzaScene(scene)) return quick ? glm::ivec2(128, 72) : glm::ivec2(192, 108);
    return quick ? glm::ivec2(64, 64) : glm::ivec2(128, 128);
}

std::vector<BenchConfiguration> suiteConfigurations(SuiteSize size, const SuiteScene& scene,
        const Settings& base, int minFrames) {
    const bool quick = size == SuiteSize::Quick;
    std::vector<BenchConfiguration> list = {
            configuration(GiMode::Direct, kSuiteDirect, {}, 0.3),
            configuration(GiMode::Voxel, kSuiteVoxel, {}, 1.0),
            configuration(GiMode::Voxel, kSuiteVoxelQuality, voxelQualityPreset(), 4.0),
            configuration(GiMode::Atlas, kSuiteAtlas, {}, 2.0),
    };
    // Last: the renderer keeps the voxel occupancy of vpl.visibility=cascade across a mode
    // switch, so a converged atlas after it would march an occupancy it did not voxelize.
    const BenchConfiguration vpl = configuration(GiMode::Vpl, kSuiteVpl, {}, 3.0);
    // The atlas' own target: voxel visibility, every sample set of atlas.target_samples
    // accumulated. Sponza's atlas is too slow on a software rasterizer for the CI form.
    if (quick && isSponzaScene(scene)) {
        list.push_back(vpl);
        return list;
    }
    // The CI form stops at kQuickTargetSamples: it guards against regressions, the full form
    // measures convergence.
    const int samples = std::max(1, base.atlas.samples);
    const int target = quick ? std::min(base.atlas.targetSamples, kQuickTargetSamples)
                             : base.atlas.targetSamples;
    const int frames = std::max(minFrames, (target + samples - 1) / samples);
    std::vector<SettingChange> changes = {{"atlas.visibility", "voxel"}};
    if (target != base.atlas.targetSamples) {
        changes.push_back({"atlas.target_samples", std::to_string(target)});
    }
    BenchConfiguration converged =
            configuration(GiMode::Atlas, kSuiteAtlasConverged, std::move(changes), 6.0 * frames);
    converged.accumulatedFrames = frames;
    list.push_back(converged);
    list.push_back(vpl);
    return list;
}

SuiteTarget suiteTarget(SceneKind kind, const std::string& configuration) {
    SuiteTarget target;
    if (isCornell(kind) && (configuration == kSuiteVoxel || configuration == kSuiteVpl)) {
        target.maxRelRmseIndirect = 0.30;
        target.minEnergy = 0.9;
        target.maxEnergy = 1.1;
    } else if (isCornell(kind) && configuration == kSuiteVoxelQuality) {
        target.maxRelRmseIndirect = 0.20;
    } else if (isCornell(kind) && configuration == kSuiteAtlasConverged) {
        target.maxRelRmseIndirect = 0.12;
        target.minEnergy = 0.95;
        target.maxEnergy = 1.05;
    } else if (kind == SceneKind::Sponza && configuration == kSuiteVpl) {
        target.minEnergy = 0.85;
        target.maxEnergy = 1.15;
    } else if (kind == SceneKind::Sponza && configuration == kSuiteVoxel) {
        target.minEnergy = 0.85;
        target.maxEnergy = 1.15;
        target.maxIndirectRatioToNoGi = 0.6;
    } else if (kind == SceneKind::LeakDark && configuration == kSuiteVoxel) {
        target.maxLeak = 0.05;
    }
    return target;
}

} // namespace gi::bench
