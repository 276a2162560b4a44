#include "app/CommandLine.h"

#include "core/ImageIO.h"

#include <glm/gtc/constants.hpp>

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace gi::app {
namespace {

std::vector<std::string> split(const std::string& text, char separator) {
    std::vector<std::string> parts;
    std::string part;
    std::istringstream stream(text);
    while (std::getline(stream, part, separator)) parts.push_back(part);
    if (!text.empty() && text.back() == separator) parts.emplace_back();
    return parts;
}

bool parseFloat(const std::string& text, float& value) {
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    return ec == std::errc() && end == text.data() + text.size() && std::isfinite(value);
}

bool parseInt(const std::string& text, int& value) {
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    return ec == std::errc() && end == text.data() + text.size();
}

bool parseFloats(const std::string& text, std::size_t count, std::vector<float>& values) {
    const std::vector<std::string> parts = split(text, ',');
    if (parts.size() != count) return false;
    values.resize(count);
    for (std::size_t i = 0; i < count; ++i) {
        if (!parseFloat(parts[i], values[i])) return false;
    }
    return true;
}

bool parseVec3(const std::string& text, glm::vec3& v) {
    std::vector<float> values;
    if (!parseFloats(text, 3, values)) return false;
    v = {values[0], values[1], values[2]};
    return true;
}

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

bool parseLightSpec(const std::string& text, scene::Light& light, std::string& error) {
    const std::vector<std::string> parts = split(text, ':');
    const std::string kind = parts.empty() ? "" : parts[0];
    error = "--light '" + text + "': expected point:x,y,z:r,g,b:intensity, "
            "spot:x,y,z:dx,dy,dz:r,g,b:intensity[:inner_deg,outer_deg] or "
            "dir:dx,dy,dz:r,g,b:intensity";
    light = scene::Light{};
    light.name = "command-line " + kind;
    auto direction = [&](const std::string& part) {
        glm::vec3 d;
        if (!parseVec3(part, d) || glm::length(d) < 1e-12f) return false;
        light.direction = glm::normalize(d);
        return true;
    };
    auto colorAndIntensity = [&](const std::string& color, const std::string& intensity) {
        return parseVec3(color, light.color) && parseFloat(intensity, light.intensity) &&
               light.intensity >= 0.0f && light.color.r >= 0.0f && light.color.g >= 0.0f &&
               light.color.b >= 0.0f;
    };
    if (kind == "point" && parts.size() == 4) {
        light.type = scene::LightType::Point;
        if (!parseVec3(parts[1], light.position) || !colorAndIntensity(parts[2], parts[3])) return false;
    } else if (kind == "dir" && parts.size() == 4) {
        light.type = scene::LightType::Directional;
        if (!direction(parts[1]) || !colorAndIntensity(parts[2], parts[3])) return false;
    } else if (kind == "spot" && (parts.size() == 5 || parts.size() == 6)) {
        light.type = scene::LightType::Spot;
        if (!parseVec3(parts[1], light.position) || !direction(parts[2]) ||
                !colorAndIntensity(parts[3], parts[4])) {
            return false;
        }
        if (parts.size() == 6) {
            std::vector<float> cone;
            if (!parseFloats(parts[5], 2, cone) || cone[0] < 0.0f || cone[1] <= cone[0] ||
                    cone[1] > 90.0f) {
                error = "--light '" + text + "': cone angles must satisfy 0 <= inner < outer <= 90";
                return false;
            }
            light.innerConeAngle = glm::radians(cone[0]);
            light.outerConeAngle = glm::radians(cone[1]);
        }
    } else {
        return false;
    }
    error.clear();
    return true;
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

bool parseKeyEvents(const std::string& text, std::vector<KeyEvent>& keys, std::string& error) {
    for (const std::string& item : split(text, ',')) {
        const std::size_t colon = item.find(':');
        KeyEvent event;
        if (colon == std::string::npos || !parseInt(item.substr(0, colon), event.frame) ||
                event.frame < 0 || colon + 1 >= item.size()) {
            error = "--keys '" + text + "': expected FRAME:KEY,... (e.g. 2:G,4:F12)";
            return false;
        }
        event.key = item.substr(colon + 1);
        keys.push_back(event);
    }
    return true;
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
    auto value = [&](const std::string& flag) -> std::optional<std::string> {
        if (i + 1 >= argc) {
            error = flag + " needs a value";
            return std::nullopt;
        }
        return std::string(argv[++i]);
    };
    auto allowed = [&](const std::string& flag, std::initializer_list<Command> commands) {
        for (Command c : commands) {
            if (c == command) return true;
        }
        error = flag + " is not an option of this command (see --help)";
        return false;
    };

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
            sawScene = true;
            continue;
        }
        std::optional<std::string> v;
        if (arg == "--out") {
            if (!allowed(arg, {Command::Render}) || !(v = value(arg))) return std::nullopt;
            if (!core::hasExtension(*v, ".png")) {
                error = "--out " + *v + ": the output image must be a .png file";
                return std::nullopt;
            }
            config.outPath = *v;
        } else if (arg == "--hdr") {
            if (!allowed(arg, {Command::Render}) || !(v = value(arg))) return std::nullopt;
            if (!core::hasExtension(*v, ".exr") && !core::hasExtension(*v, ".pfm")) {
                error = "--hdr " + *v + ": the HDR image must be a .exr or .pfm file";
                return std::nullopt;
            }
            config.hdrPath = *v;
        } else if (arg == "--timings") {
            if (!allowed(arg, {Command::Render}) || !(v = value(arg))) return std::nullopt;
            config.timingsPath = *v;
        } else if (arg == "--mode") {
            if (!allowed(arg, {Command::Render}) || !(v = value(arg))) return std::nullopt;
            if (*v == "direct") config.mode = render::GiMode::Direct;
            else if (*v == "voxel") config.mode = render::GiMode::Voxel;
            else if (*v == "atlas") config.mode = render::GiMode::Atlas;
            else if (*v == "reference") config.mode = render::GiMode::Reference;
            else {
                error = "--mode '" + *v + "': expected direct, voxel, atlas or reference";
                return std::nullopt;
            }
        } else if (arg == "--output") {
            if (!allowed(arg, {Command::Render}) || !(v = value(arg))) return std::nullopt;
            const auto output = render::parseOutputComponent(*v);
            if (!output) {
                error = "--output '" + *v + "': expected final, direct, indirect, voxel-albedo, "
                        "voxel-irradiance or voxel-normal";
                return std::nullopt;
            }
            config.output = *output;
        } else if (arg == "--width" || arg == "--height") {
            if (!allowed(arg, {Command::Render, Command::View}) || !(v = value(arg))) return std::nullopt;
            int n = 0;
            if (!parseInt(*v, n) || n < 1 || n > 16384) {
                error = arg + " '" + *v + "': expected an integer in [1, 16384]";
                return std::nullopt;
            }
            (arg == "--width" ? config.width : config.height) = n;
        } else if (arg == "--camera") {
            if (!allowed(arg, {Command::Render, Command::View}) || !(v = value(arg))) return std::nullopt;
            int index = 0;
            if (parseInt(*v, index)) {
                if (index < 0) {
                    error = "--camera " + *v + ": a camera index cannot be negative";
                    return std::nullopt;
                }
                config.cameraIndex = index;
            } else {
                CameraSpec spec;
                if (!parseCameraSpec(*v, spec, error)) return std::nullopt;
                config.cameraSpec = spec;
            }
        } else if (arg == "--light") {
            if (!allowed(arg, {Command::Render, Command::View}) || !(v = value(arg))) return std::nullopt;
            if (*v == "none") {
                config.noLights = true;
                continue;
            }
            scene::Light light;
            if (!parseLightSpec(*v, light, error)) return std::nullopt;
            config.extraLights.push_back(light);
        } else if (arg == "--gl") {
            if (!allowed(arg, {Command::Render, Command::Bench}) || !(v = value(arg))) return std::nullopt;
            const auto provider = platform::parseProvider(*v);
            if (!provider) {
                error = "--gl '" + *v + "': expected egl or osmesa";
                return std::nullopt;
            }
            config.gl = *provider;
            config.glExplicit = true;
        } else if (arg == "--set") {
            if (!allowed(arg, {Command::Render, Command::View, Command::Bench, Command::Info}) || !(v = value(arg))) {
                return std::nullopt;
            }
            if (!applySetting(config.settings, *v, error)) return std::nullopt;
        } else if (arg == "--move") {
            if (!allowed(arg, {Command::Render}) || !(v = value(arg))) return std::nullopt;
            if (!parseVec3(*v, config.cameraMove) || glm::length(config.cameraMove) > 1e6f) {
                error = "--move '" + *v + "': expected DX,DY,DZ in metres per frame";
                return std::nullopt;
            }
        } else if (arg == "--animate") {
            if (!allowed(arg, {Command::Render}) || !(v = value(arg))) return std::nullopt;
            if (!parseFloat(*v, config.animationStep) || !(config.animationStep >= 0.0f) ||
                    config.animationStep > 1e3f) {
                error = "--animate '" + *v + "': expected seconds per frame between 0 and 1000";
                return std::nullopt;
            }
        } else if (arg == "--time") {
            if (!allowed(arg, {Command::Render, Command::View}) || !(v = value(arg))) return std::nullopt;
            if (!parseFloat(*v, config.animationTime) || config.animationTime < 0.0f ||
                    config.animationTime > 1e6f) {
                error = "--time '" + *v + "': expected seconds between 0 and 1e6";
                return std::nullopt;
            }
        } else if (arg == "--frames") {
            if (!allowed(arg, {Command::View}) || !(v = value(arg))) return std::nullopt;
            if (!parseInt(*v, config.frames) || config.frames < 1) {
                error = "--frames '" + *v + "': expected a positive integer";
                return std::nullopt;
            }
        } else if (arg == "--screenshot") {
            if (!allowed(arg, {Command::View}) || !(v = value(arg))) return std::nullopt;
            if (!core::hasExtension(*v, ".png")) {
                error = "--screenshot " + *v + ": the screenshot must be a .png file";
                return std::nullopt;
            }
            config.screenshotPath = *v;
        } else if (arg == "--keys") {
            if (!allowed(arg, {Command::View}) || !(v = value(arg))) return std::nullopt;
            if (!parseKeyEvents(*v, config.keys, error)) return std::nullopt;
        } else if (arg == "--quick") {
            if (!allowed(arg, {Command::Bench})) return std::nullopt;
            config.quick = true;
        } else if (arg == "--out-dir") {
            if (!allowed(arg, {Command::Bench}) || !(v = value(arg))) return std::nullopt;
            config.outDir = *v;
        } else if (arg == "--scene") {
            if (!allowed(arg, {Command::Bench}) || !(v = value(arg))) return std::nullopt;
            config.scenePath = *v;
        } else {
            error = "unknown option '" + arg + "' (see --help)";
            return std::nullopt;
        }
    }

    if (command == Command::Render && config.outPath.empty()) {
        error = "render needs --out F.png";
        return std::nullopt;
    }
    if ((command == Command::Render || command == Command::Info) && config.scenePath.empty()) {
        error = std::string(command == Command::Render ? "render" : "info") +
                " needs a SCENE (.gltf or .glb)";
        return std::nullopt;
    }
    if (config.scenePath.empty()) config.scenePath = defaultScenePath();
    return config;
}

std::string usage(Command command) {
    switch (command) {
    case Command::Render:
        return "usage: voxatlas render SCENE --out F.png [--hdr F.exr|F.pfm]\n"
               "        [--mode direct|voxel|atlas|reference]\n"
               "        [--output final|direct|indirect|voxel-albedo|voxel-irradiance|voxel-normal]\n"
               "        [--width W --height H] [--camera N | --camera ex,ey,ez,tx,ty,tz,fovy_deg]\n"
               "        [--light KIND:...] [--gl egl|osmesa] [--set key=value ...] [--timings F.json]\n"
               "        [--time SECONDS]   (pose of the scene's glTF animations; default 0)\n"
               "        [--move DX,DY,DZ]  (the camera travels this far each frame, warm-up included:\n"
               "                            timings of a moving camera)\n"
               "        [--animate SECONDS] (the scene's animations play this long each frame, from\n"
               "                            --time: timings of animated objects)\n"
               "\n"
               "Renders one frame without a display (EGL surfaceless; OSMesa if EGL is missing\n"
               "and --gl was not given) to an sRGB PNG and optionally a linear HDR image.\n"
               "Defaults: 512x512, camera 0 of the scene, --mode direct, --output final.\n"
               "\n"
               "--light point:x,y,z:r,g,b:intensity\n"
               "        spot:x,y,z:dx,dy,dz:r,g,b:intensity[:inner_deg,outer_deg]\n"
               "        dir:dx,dy,dz:r,g,b:intensity\n"
               "        none   (no lights from the scene and no default light)\n"
               "\n"
               "--set keys (default, range):\n" + settingsHelp();
    case Command::Info:
        return "usage: voxatlas info SCENE [--set key=value ...]\n"
               "Prints counts, bounds, lights, cameras and the memory plan of a glTF scene: the\n"
               "scene's own buffers, and the GI resources the settings give it (voxel cascade,\n"
               "atlas, shadow maps). --set render.plan=adaptive shows the plan sized from the\n"
               "scene; --set voxel.resolution=64 etc. change either plan.\n";
    case Command::Bench:
        return "usage: voxatlas bench [--scene SCENE] [--quick] [--out-dir DIR] [--gl egl|osmesa]\n"
               "        [--set key=value ...]\n"
               "\n"
               "Sweeps the voxel and atlas GI settings on the Cornell box and on Sponza (--scene,\n"
               "else $VOXATLAS_SPONZA, else ../shared/assets/sponza/Sponza.gltf next to the source\n"
               "tree), times every pass, scores the indirect and final images against the cached\n"
               "ground truth, and writes bench.csv, bench.md and pareto.png to --out-dir\n"
               "(default docs/results). --quick: smaller images, 3 timed frames, 64 spp\n"
               "reference, no 2048^2 / 400-sample atlas; the full sweep: 7 frames, 256 spp.\n"
               "--set changes the base settings under every configuration\n"
               "(material.specular is always 0, voxel.cache always 0: every pass every frame).\n";
    default:
        return "usage: voxatlas [view] [SCENE] [--width W --height H] [--camera ...] [--light ...]\n"
               "        [--frames N] [--screenshot F.png] [--keys \"FRAME:KEY,...\"] [--set key=value ...]\n"
               "       voxatlas render SCENE --out F.png ...   (voxatlas render --help)\n"
               "       voxatlas bench [--scene ...] [--quick] [--out-dir DIR]\n"
               "       voxatlas info SCENE [--set key=value ...]\n"
               "SCENE defaults to the Cornell box. Without a display, view renders a headless\n"
               "screenshot instead.\n";
    }
}

} // namespace gi::app
