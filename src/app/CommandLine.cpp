#include "app/CommandLine.h"

#include "app/TextParsing.h"
#include "app/ViewOptions.h"

#include "core/ImageIO.h"

#include <glm/gtc/constants.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace gi::app {
namespace {

std::optional<Command> parseCommand(const std::string& word) {
    if (word == "view") return Command::View;
    if (word == "render") return Command::Render;
    if (word == "bench") return Command::Bench;
    if (word == "info") return Command::Info;
    return std::nullopt;
}

} // namespace

std::string dataDirectory() {
    const char* env = std::getenv("VOXATLAS_DATA_DIR");
    return env && *env ? env : VOXATLAS_DATA_DIR;
}

std::string defaultScenePath() {
    return dataDirectory() + "/assets/cornell_box/cornell_box.gltf";
}

bool parseCameraSpec(const std::string& text, CameraSpec& camera, std::string& error) {
    std::vector<float> v;
    if (!parseFloats(text, 7, v)) {
        error = "--camera '" + text + "': expected an index or ex,ey,ez,tx,ty,tz,fovy_deg";
        return false;
    }
    camera.eye = {v[0], v[1], v[2]};
    camera.target = {v[3], v[4], v[5]};
    camera.yfovDegrees = v[6];
    if (!(camera.yfovDegrees > 0.0f && camera.yfovDegrees < 180.0f)) {
        error = "--camera '" + text + "': fovy_deg must be in (0, 180)";
        return false;
    }
    if (glm::length(camera.target - camera.eye) <= 0.0f) {
        error = "--camera '" + text + "': eye and target coincide";
        return false;
    }
    return true;
}

namespace {

// The commands an option belongs to, one bit per Command.
using CommandMask = unsigned;
constexpr CommandMask bit(Command command) { return 1u << unsigned(command); }
constexpr CommandMask kRender = bit(Command::Render);
constexpr CommandMask kView = bit(Command::View);
constexpr CommandMask kBench = bit(Command::Bench);
constexpr CommandMask kInfo = bit(Command::Info);

// Applies one option's value (empty for a switch) to the config; false with the error set.
using ApplyOption = bool (*)(Config& config, const std::string& flag, const std::string& value,
        std::string& error);

struct OptionSpec {
    const char* flag;
    CommandMask commands;
    bool takesValue;
    ApplyOption apply;
};

// "a, b, c or d" of the names in a catalog.
template <class Entries>
std::string nameList(const Entries& entries) {
    std::string list;
    for (std::size_t i = 0; i < entries.size(); ++i) {
        if (i > 0) list += i + 1 == entries.size() ? " or " : ", ";
        list += entries[i].name;
    }
    return list;
}

bool applyOut(Config& config, const std::string&, const std::string& v, std::string& error) {
    if (!core::hasExtension(v, ".png")) {
        error = "--out " + v + ": the output image must be a .png file";
        return false;
    }
    config.outPath = v;
    return true;
}

bool applyHdr(Config& config, const std::string&, const std::string& v, std::string& error) {
    if (!core::hasExtension(v, ".exr") && !core::hasExtension(v, ".pfm")) {
        error = "--hdr " + v + ": the HDR image must be a .exr or .pfm file";
        return false;
    }
    config.hdrPath = v;
    return true;
}

bool applyTimings(Config& config, const std::string&, const std::string& v, std::string&) {
    config.timingsPath = v;
    return true;
}

bool applyMode(Config& config, const std::string&, const std::string& v, std::string& error) {
    const auto mode = render::parseGiMode(v);
    if (!mode) {
        error = "--mode '" + v + "': expected " + nameList(render::modeCatalog());
        return false;
    }
    config.mode = *mode;
    config.modeGiven = true;
    return true;
}

bool applyOutput(Config& config, const std::string&, const std::string& v, std::string& error) {
    const auto output = render::parseOutputComponent(v);
    if (!output) {
        error = "--output '" + v + "': expected " + nameList(render::outputCatalog());
        return false;
    }
    config.output = *output;
    return true;
}

bool applySize(Config& config, const std::string& flag, const std::string& v, std::string& error) {
    int n = 0;
    if (!parseInt(v, n) || n < 1 || n > 16384) {
        error = flag + " '" + v + "': expected an integer in [1, 16384]";
        return false;
    }
    (flag == "--width" ? config.width : config.height) = n;
    return true;
}

bool applyCamera(Config& config, const std::string&, const std::string& v, std::string& error) {
    int index = 0;
    if (!parseInt(v, index)) {
        CameraSpec spec;
        if (!parseCameraSpec(v, spec, error)) return false;
        config.cameraSpec = spec;
        return true;
    }
    if (index < 0) {
        error = "--camera " + v + ": a camera index cannot be negative";
        return false;
    }
    config.cameraIndex = index;
    return true;
}

bool applyLight(Config& config, const std::string&, const std::string& v, std::string& error) {
    if (v == "none") {
        config.noLights = true;
        return true;
    }
    scene::Light light;
    if (!parseLightSpec(v, light, error)) return false;
    config.extraLights.push_back(light);
    return true;
}

bool applyGl(Config& config, const std::string&, const std::string& v, std::string& error) {
    const auto provider = platform::parseProvider(v);
    if (!provider) {
        error = "--gl '" + v + "': expected egl or osmesa";
        return false;
    }
    config.gl = *provider;
    config.glExplicit = true;
    return true;
}

bool applySet(Config& config, const std::string&, const std::string& v, std::string& error) {
    if (!applySetting(config.settings, v, error)) return false;
    config.settingKeys.push_back(v.substr(0, v.find('=')));
    return true;
}

bool applyExposure(Config& config, const std::string&, const std::string& v,
        std::string& error) {
    config.exposureGiven = true;
    config.toneMapping.autoExposure = v == "auto";
    if (config.toneMapping.autoExposure) return true;
    if (!parseFloat(v, config.toneMapping.ev) ||
            std::abs(config.toneMapping.ev) > core::kMaxExposureEv) {
        error = "--exposure '" + v + "': expected auto or stops (EV) between -20 and 20";
        return false;
    }
    return true;
}

bool applyToneCurve(Config& config, const std::string&, const std::string& v,
        std::string& error) {
    const std::optional<core::ToneCurve> curve = core::parseToneCurve(v);
    if (!curve) {
        error = "--tonemap '" + v + "': expected none or filmic";
        return false;
    }
    config.toneMapping.curve = *curve;
    config.toneCurveGiven = true;
    return true;
}

bool applyMove(Config& config, const std::string&, const std::string& v, std::string& error) {
    if (!parseVec3(v, config.cameraMove) || glm::length(config.cameraMove) > 1e6f) {
        error = "--move '" + v + "': expected DX,DY,DZ in metres per frame";
        return false;
    }
    return true;
}

bool applyAnimate(Config& config, const std::string&, const std::string& v, std::string& error) {
    if (!parseFloat(v, config.animationStep) || !(config.animationStep >= 0.0f) ||
            config.animationStep > 1e3f) {
        error = "--animate '" + v + "': expected seconds per frame between 0 and 1000";
        return false;
    }
    return true;
}

bool applyTime(Config& config, const std::string&, const std::string& v, std::string& error) {
    if (!parseFloat(v, config.animationTime) || config.animationTime < 0.0f ||
            config.animationTime > 1e6f) {
        error = "--time '" + v + "': expected seconds between 0 and 1e6";
        return false;
    }
    return true;
}

bool applyQuick(Config& config, const std::string&, const std::string&, std::string&) {
    config.sweep = bench::SweepSize::Quick;
    return true;
}

bool applySweep(Config& config, const std::string& flag, const std::string& v, std::string& error) {
    const std::optional<bench::SweepSize> size = bench::parseSweepSize(v);
    if (!size) {
        error = flag + " '" + v + "': expected smoke, quick or full";
        return false;
    }
    config.sweep = *size;
    return true;
}

bool applySuite(Config& config, const std::string& flag, const std::string& v, std::string& error) {
    const std::optional<bench::SuiteSize> size = bench::parseSuiteSize(v);
    if (!size) {
        error = flag + " '" + v + "': expected quick or full";
        return false;
    }
    config.suite = *size;
    return true;
}

bool applyTemporal(Config& config, const std::string&, const std::string&, std::string&) {
    config.temporal = true;
    return true;
}

bool applyOutDir(Config& config, const std::string&, const std::string& v, std::string&) {
    config.outDir = v;
    return true;
}

bool applyScene(Config& config, const std::string&, const std::string& v, std::string&) {
    config.scenePath = v;
    config.sceneGiven = true;
    return true;
}

constexpr OptionSpec kOptions[] = {
        {"--out", kRender, true, applyOut},
        {"--hdr", kRender | kView, true, applyHdr},
        {"--timings", kRender, true, applyTimings},
        {"--mode", kRender | kView, true, applyMode},
        {"--output", kRender, true, applyOutput},
        {"--width", kRender | kView, true, applySize},
        {"--height", kRender | kView, true, applySize},
        {"--camera", kRender | kView, true, applyCamera},
        {"--light", kRender | kView, true, applyLight},
        {"--gl", kRender | kBench, true, applyGl},
        {"--set", kRender | kView | kBench | kInfo, true, applySet},
        {"--exposure", kRender | kView, true, applyExposure},
        {"--tonemap", kRender | kView, true, applyToneCurve},
        {"--move", kRender | kView, true, applyMove},
        {"--move-frames", kView, true, applyMoveFrames},
        {"--animate", kRender, true, applyAnimate},
        {"--time", kRender | kView, true, applyTime},
        {"--frames", kView, true, applyFrames},
        {"--screenshot", kView, true, applyScreenshot},
        {"--keys", kView, true, applyKeys},
        {"--drop", kView, true, applyDrop},
        {"--quick", kBench, false, applyQuick},
        {"--sweep", kBench, true, applySweep},
        {"--suite", kBench, true, applySuite},
        {"--temporal", kBench, false, applyTemporal},
        {"--out-dir", kBench, true, applyOutDir},
        {"--scene", kBench, true, applyScene},
};

const OptionSpec* findOption(const std::string& flag) {
    for (const OptionSpec& option : kOptions) {
        if (flag == option.flag) return &option;
    }
    return nullptr;
}

// The checks no single option can make: what each command cannot do without.
bool checkRequired(Config& config, std::string& error) {
    const Command command = config.command;
    if (command == Command::Render && config.outPath.empty()) {
        error = "render needs --out F.png";
        return false;
    }
    if ((command == Command::Render || command == Command::Info) && config.scenePath.empty()) {
        error = std::string(command == Command::Render ? "render" : "info") +
                " needs a SCENE (.gltf or .glb)";
        return false;
    }
    if (command == Command::View && !render::modeEntry(config.mode).gpu) {
        error = std::string("--mode ") + render::modeEntry(config.mode).name +
                ": the viewer shows the real-time modes only (render --mode " +
                render::modeEntry(config.mode).name + " for a still image)";
        return false;
    }
    if (config.scenePath.empty()) config.scenePath = defaultScenePath();
    if (command == Command::View) {
        // The viewer's look; the headless fallback (a render) inherits it from here. It opens
        // with global illumination: a viewer of a GI program that starts on direct light
        // shows a new user none of what it is for.
        if (!config.modeGiven) config.mode = render::GiMode::Voxel;
        if (!config.exposureGiven) config.toneMapping.autoExposure = true;
        if (!config.toneCurveGiven) config.toneMapping.curve = core::ToneCurve::Filmic;
    }
    return true;
}

} // namespace

bool applyOption(Config& config, const std::string& flag, const std::string& value,
        std::string& error) {
    const OptionSpec* option = findOption(flag);
    if (!option) {
        error = "unknown option '" + flag + "'";
        return false;
    }
    return option->apply(config, flag, value, error);
}

std::optional<Config> parseCommandLine(int argc, const char* const* argv, std::string& error) {
    Config config;
    int i = 1;
    if (i < argc) {
        if (auto command = parseCommand(argv[i])) {
            config.command = *command;
            ++i;
        }
    }
    const Command command = config.command;
    bool sawScene = false;
    for (; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "-h" || arg == "--help") {
            config.helpFor = command;
            config.command = Command::Help;
            return config;
        }
        if (arg.rfind("--", 0) != 0 || arg == "--") {
            if (sawScene) {
                error = "unexpected argument '" + arg + "' (only one scene may be given)";
                return std::nullopt;
            }
            config.scenePath = arg;
            config.sceneGiven = true;
            sawScene = true;
            continue;
        }
        const OptionSpec* option = findOption(arg);
        if (!option) {
            error = "unknown option '" + arg + "' (see --help)";
            return std::nullopt;
        }
        if ((option->commands & bit(command)) == 0) {
            error = arg + " is not an option of this command (see --help)";
            return std::nullopt;
        }
        if (option->takesValue && i + 1 >= argc) {
            error = arg + " needs a value";
            return std::nullopt;
        }
        const std::string value = option->takesValue ? argv[++i] : "";
        if (!option->apply(config, arg, value, error)) return std::nullopt;
    }
    if (!checkRequired(config, error) ||
            !choosePlan(config.settings, config.settingKeys, config.plan, error)) {
        return std::nullopt;
    }
    return config;
}

} // namespace gi::app
