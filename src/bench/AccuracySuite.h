// The accuracy scoreboard (`voxatlas bench --suite`): every scene of assets/scene_suite/ plus
// two lightings of Sponza, each rendered in direct, voxel (default and the quality preset),
// atlas (default, and progressive to convergence with voxel visibility) and VPL mode (default),
// and scored against
// the one-bounce path tracer. A result on one scene is not a result: every GI change answers to
// all of them, with one set of defaults.
//
// What is defined here is data: the scenes (file, camera and lights, as on the command line),
// the configurations, the image sizes and the targets each score is held to. The app layer
// loads the scenes, BenchRunner renders and scores them, AccuracyReport writes the page.
#pragma once

#include "bench/BenchSweep.h"
#include "core/Settings.h"

#include <glm/glm.hpp>

#include <optional>
#include <string>
#include <vector>

namespace gi::bench {

enum class SuiteSize {
    Quick,   // the CI form: small images, a cheaper converged atlas, Sponza without its atlas
    Full,    // the docs/ form
};

[[nodiscard]] const char* suiteSizeName(SuiteSize size);
[[nodiscard]] std::optional<SuiteSize> parseSuiteSize(const std::string& name);

// What a scene is there to test, which decides the targets it is held to.
enum class SceneKind {
    Cornell,     // a variant of the Cornell box: relative RMSE and energy targets
    Sponza,      // energy and the indirect error against the no-GI baseline's
    LeakLit,     // the lit room of the thin-wall pair: scored, and the leak's denominator
    LeakDark,    // the dark room: its indirect light over the lit room's is the leak
    Energy,      // the closed white box: energy balance
    Scored,      // scored, with no target of its own
};

struct SuiteScene {
    std::string name;                  // table name, also --scene's filter
    std::string file;                  // relative to the source tree; empty = Sponza
    std::string camera;                // --camera: an index or ex,ey,ez,tx,ty,tz,fovy
    std::vector<std::string> lights;   // --light texts, in order ("none" first replaces the file's)
    SceneKind kind = SceneKind::Cornell;
    std::string tests;                 // what the scene tests, one line for the report
};

[[nodiscard]] const std::vector<SuiteScene>& suiteScenes();
[[nodiscard]] bool isSponzaScene(const SuiteScene& scene);

// Output pixels of a scene's images.
[[nodiscard]] glm::ivec2 suiteImageSize(SuiteSize size, const SuiteScene& scene);

// The configurations' short names, which the CSV, the report and the CI thresholds use.
inline constexpr const char* kSuiteDirect = "direct";
inline constexpr const char* kSuiteVoxel = "voxel";
inline constexpr const char* kSuiteVoxelQuality = "voxel quality";
inline constexpr const char* kSuiteAtlas = "atlas";
inline constexpr const char* kSuiteAtlasConverged = "atlas converged";
inline constexpr const char* kSuiteVpl = "vpl";

// The configurations scored on `scene`; BenchConfiguration::label is one of the names above.
// The converged atlas accumulates base.atlas.target_samples in sets of base.atlas.samples, and
// at least `minFrames` (warm-up + timed) frames.
[[nodiscard]] std::vector<BenchConfiguration> suiteConfigurations(SuiteSize size,
        const SuiteScene& scene, const Settings& base, int minFrames);

// The targets of the accuracy issue a score is held to; unset fields do not apply.
struct SuiteTarget {
    std::optional<double> maxRelRmseIndirect;
    std::optional<double> minEnergy, maxEnergy;       // indirect energy ratio
    // relRmseIndirect / the direct mode's: the targets are all on the indirect term,
    // and its no-GI baseline for Sponza (2.49 against voxel GI's 2.16) is an indirect error.
    std::optional<double> maxIndirectRatioToNoGi;
    std::optional<double> maxLeak;                    // dark room over lit room, indirect
    bool any() const {
        return maxRelRmseIndirect || minEnergy || maxIndirectRatioToNoGi || maxLeak;
    }
};

[[nodiscard]] SuiteTarget suiteTarget(SceneKind kind, const std::string& configuration);

} // namespace gi::bench
