// The command line of DESIGN.md parsed into one Config. Every flag is validated here
// (ranges, file extensions, numbers), so commands start only with good input; an error is
// one line, and main turns it into exit status 2.
#pragma once

#include "app/LightSpec.h"
#include "app/PlanChoice.h"
#include "bench/AccuracySuite.h"
#include "bench/BenchSweep.h"

#include "platform/GlContext.h"
#include "render/OutputCatalog.h"
#include "core/Settings.h"
#include "core/ToneMap.h"
#include "scene/Scene.h"

#include <optional>
#include <string>
#include <vector>

namespace gi::app {

enum class Command { View, Render, Bench, Info, Help };

// `--camera ex,ey,ez,tx,ty,tz,fovy_deg`
struct CameraSpec {
    glm::vec3 eye{0.0f}, target{0.0f, 0.0f, -1.0f};
    float yfovDegrees = 45.0f;
};

// `view --keys "FRAME:KEY,..."`: a key press replayed at a frame, for scripted viewer runs.
struct KeyEvent {
    int frame = 0;
    std::string key;   // GLFW-style name: "G", "1", "F12", "SPACE", ...
};

// `view --drop FRAME:FILE`: a file dropped on the window at a frame, for scripted viewer runs.
struct DropEvent {
    int frame = 0;
    std::string path;
};

struct Config {
    Command command = Command::View;
    Command helpFor = Command::View;        // Help: which command's help to print
    std::string scenePath;                   // empty = the default scene (Cornell box)
    bool sceneGiven = false;                 // SCENE or --scene was on the command line
    std::string outPath;                     // render: PNG
    std::string hdrPath;                     // render, view: .exr or .pfm
    std::string timingsPath;                 // render: JSON
    render::GiMode mode = render::GiMode::Direct;   // view: voxel unless --mode is given
    bool modeGiven = false;
    render::OutputComponent output = render::OutputComponent::Final;
    int width = 0, height = 0;               // 0 = the command's default
    int cameraIndex = 0;
    std::optional<CameraSpec> cameraSpec;
    std::vector<scene::Light> extraLights;   // --light
    bool noLights = false;                   // --light none: no lights at all, not even the default
    platform::HeadlessProvider gl = platform::HeadlessProvider::Egl;
    bool glExplicit = false;                 // --gl given: no silent fallback
    Settings settings;
    std::vector<std::string> settingKeys;    // the keys --set gave, in order
    PlanChoice plan;                         // render.plan as settled from them (PlanChoice.h)
    // --exposure, --tonemap: render defaults to exposure 0 and no curve (linear PNGs), view
    // to auto exposure and the filmic curve; the flags say what was given.
    core::ToneMapping toneMapping;
    bool exposureGiven = false, toneCurveGiven = false;
    // view
    int frames = 0;                          // 0 = interactive
    float animationTime = 0.0f;              // --time: seconds into the scene's animations
    glm::vec3 cameraMove{0.0f};              // --move: metres the camera travels per frame
    int moveFrames = 0;                      // view --move-frames: frames that move; 0 = all
    float animationStep = 0.0f;              // --animate: animation seconds played per frame
    std::string screenshotPath;
    std::vector<KeyEvent> keys;
    std::vector<DropEvent> drops;
    // bench
    bench::SweepSize sweep = bench::SweepSize::Full;   // --sweep, --quick
    std::string outDir;
    std::optional<bench::SuiteSize> suite;             // --suite: the accuracy scoreboard
    bool temporal = false;                             // --temporal: flicker and trails
};

[[nodiscard]] std::optional<Config> parseCommandLine(int argc, const char* const* argv,
        std::string& error);

// The source tree holding assets/, shaders/ and scripts/: $VOXATLAS_DATA_DIR, else the one
// this build was configured from.
[[nodiscard]] std::string dataDirectory();

// Path of the default scene (assets/cornell_box/cornell_box.gltf in the source tree).
[[nodiscard]] std::string defaultScenePath();

// Applies one command-line option as if it had been given ("--camera", "1"): how the accuracy
// suite sets each of its scenes' cameras and lights from their command-line texts.
[[nodiscard]] bool applyOption(Config& config, const std::string& flag, const std::string& value,
        std::string& error);

[[nodiscard]] bool parseCameraSpec(const std::string& text, CameraSpec& camera, std::string& error);
[[nodiscard]] bool parseKeyEvents(const std::string& text, std::vector<KeyEvent>& keys,
        std::string& error);
[[nodiscard]] bool parseDropEvent(const std::string& text, DropEvent& drop, std::string& error);

} // namespace gi::app
