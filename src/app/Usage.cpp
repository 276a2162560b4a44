#include "app/Usage.h"

#include "render/OutputCatalog.h"
#include "core/Settings.h"

#include <cstdio>
#include <sstream>

namespace gi::app {
namespace {

std::string modeChoices() {
    std::string choices;
    for (const render::ModeEntry& entry : render::modeCatalog()) {
        if (!choices.empty()) choices += '|';
        choices += entry.name;
    }
    return choices;
}

std::string modesHelp() {
    std::string text;
    for (const render::ModeEntry& entry : render::modeCatalog()) {
        char line[160];
        std::snprintf(line, sizeof line, "  %-17s %s\n", entry.name, entry.description);
        text += line;
    }
    return text;
}

// Which modes show an output: "all modes" or the names, e.g. "atlas only".
std::string modesOf(const render::OutputEntry& output) {
    if (output.modes == render::kAllModes) return "all modes";
    std::string names;
    for (const render::ModeEntry& mode : render::modeCatalog()) {
        if (output.modes & render::modeBit(mode.mode)) {
            names += (names.empty() ? "" : ", ") + std::string(mode.name);
        }
    }
    return names + " only";
}

std::string outputsHelp() {
    std::string text;
    for (const render::OutputEntry& entry : render::outputCatalog()) {
        char line[200];
        std::snprintf(line, sizeof line, "  %-17s %s (%s)\n", entry.name, entry.description,
                modesOf(entry).c_str());
        text += line;
    }
    return text;
}

// The lines of settingsHelp() for the viewer's own keys (view.*).
std::string viewSettingsHelp() {
    std::istringstream lines(settingsHelp());
    std::string line, help;
    while (std::getline(lines, line)) {
        if (line.rfind("  view.", 0) == 0) help += line + "\n";
    }
    return help;
}

} // namespace

std::string usage(Command command) {
    switch (command) {
    case Command::Render:
        return "usage: voxatlas render SCENE --out F.png [--hdr F.exr|F.pfm]\n"
               "        [--mode " + modeChoices() + "] [--output OUTPUT]\n"
               "        [--width W --height H] [--camera N | --camera ex,ey,ez,tx,ty,tz,fovy_deg]\n"
               "        [--light KIND:...] [--gl egl|osmesa] [--set key=value ...] [--timings F.json]\n"
               "        [--time SECONDS]   (pose of the scene's glTF animations; default 0)\n"
               "        [--move DX,DY,DZ]  (the camera travels this far each frame, warm-up included:\n"
               "                            timings of a moving camera)\n"
               "        [--animate SECONDS] (the scene's animations play this long each frame, from\n"
               "                            --time: timings of animated objects)\n"
               "        [--exposure auto|EV] [--tonemap none|filmic] (PNG only; default 0, none)\n"
               "\n"
               "Renders one frame without a display (EGL surfaceless; OSMesa if EGL is missing\n"
               "and --gl was not given) to an sRGB PNG and optionally a linear HDR image.\n"
               "Defaults: 512x512, camera 0 of the scene, --mode direct, --output final.\n"
               "\n"
               "--exposure EV multiplies radiance by 2^EV (-20..20) before the PNG is encoded;\n"
               "--exposure auto: 0.18 / the log-average luminance of the pixels showing geometry.\n"
               "--tonemap filmic: the ACES fit of Narkowicz (2015) after the exposure. The\n"
               "defaults keep the PNG linear at exposure 1; the HDR image is always linear.\n"
               "\n"
               "render.plan=adaptive (the default) sizes the voxel cascade and the atlas from the\n"
               "scene; --set of a key marked 'fixed plan' selects render.plan=fixed (the thesis'\n"
               "allocation) and says so on stderr. `voxatlas info SCENE` shows the plan.\n"
               "\n"
               "--light point:x,y,z:r,g,b:intensity\n"
               "        spot:x,y,z:dx,dy,dz:r,g,b:intensity[:inner_deg,outer_deg]\n"
               "        dir:dx,dy,dz:r,g,b:intensity\n"
               "        sky:r,g,b:intensity   (radiance colour x intensity from every direction)\n"
               "        rect:cx,cy,cz:ux,uy,uz:vx,vy,vz:r,g,b:radiance   (area light: centre +-\n"
               "             u/2 +- v/2, emitting colour x radiance towards cross(u, v))\n"
               "        none   (no lights from the scene and no default light)\n"
               "\n"
               "--mode:\n" + modesHelp() + "\n"
               "--output OUTPUT (debug views only in their mode):\n" + outputsHelp() + "\n"
               "--set keys (default, range):\n" + settingsHelp();
    case Command::Info:
        return "usage: voxatlas info SCENE [--set key=value ...]\n"
               "Prints counts, bounds, lights, cameras and the memory plan of a glTF scene: the\n"
               "scene's own buffers, and the GI resources the settings give it (voxel cascade,\n"
               "atlas, shadow maps), and which plan is active and why: the adaptive plan (the\n"
               "default) sizes voxel.cascades, voxel.extent, voxel.scene_centred,\n"
               "voxel.clamp_centre and atlas.resolution from the scene; setting one of them\n"
               "selects render.plan=fixed (the thesis' allocation). --set voxel.resolution=64\n"
               "etc. change either plan.\n";
    case Command::Bench:
        return "usage: voxatlas bench [--scene SCENE] [--sweep smoke|quick|full] [--quick]\n"
               "        [--out-dir DIR] [--gl egl|osmesa]\n"
               "        [--set key=value ...]\n"
               "\n"
               "Sweeps the voxel and atlas GI settings on the Cornell box and on Sponza (--scene,\n"
               "else $VOXATLAS_SPONZA, else ../shared/assets/sponza/Sponza.gltf next to the source\n"
               "tree), times every pass, scores the indirect and final images against the cached\n"
               "ground truth, and writes bench.csv, bench.md and pareto.png to --out-dir\n"
               "(default docs/results). --sweep full (the default): 7 timed frames, 256 spp\n"
               "reference. --sweep quick (or --quick): smaller images, 3 timed frames, 64 spp\n"
               "reference, no 2048^2 / 400-sample atlas. --sweep smoke: as quick, with one or two\n"
               "configurations per mode (minutes; the form CI runs). --scene naming the Cornell\n"
               "box measures it alone.\n"
               "--set changes the base settings under every configuration\n"
               "(material.specular is always 0, voxel.cache always 0: every pass every frame;\n"
               "render.plan is fixed, the thesis' allocation, unless --set render.plan is given).\n"
               "\n"
               "       voxatlas bench --suite quick|full [--scene NAME,...] [--out-dir DIR]\n"
               "\n"
               "The accuracy scoreboard: every scene of assets/scene_suite/ and two lightings of\n"
               "Sponza in direct, voxel (defaults, quality preset) and atlas mode (defaults, and\n"
               "converged with voxel visibility), scored against the one-bounce path tracer.\n"
               "Writes results-accuracy.md, accuracy.csv and images/accuracy_*.png to --out-dir\n"
               "(default docs). full: 128x128 (Sponza 192x108), 1024 spp references; quick (CI):\n"
               "64x64 (128x72), 256 spp, the converged atlas at 400 samples and not in Sponza.\n"
               "--scene picks suite scenes by name. Surfaces are Lambertian unless --set\n"
               "material.model=gltf: then the GPU and the path tracer both use glTF's BRDF.\n"
               "\n"
               "       voxatlas bench --temporal [--quick] [--out-dir DIR]\n"
               "\n"
               "Temporal stability: the mean relative frame-to-frame change of the indirect term\n"
               "against the direct term's along slow camera paths (Sponza down the atrium at\n"
               "10 cm per frame, the Cornell box sideways), in voxel and atlas mode (and VPL\n"
               "mode in the full form) with and without gi.temporal_filter, and the trail the\n"
               "animated Cornell box's cube leaves.\n"
               "Writes results-temporal.md and images/temporal_*.png to --out-dir (default\n"
               "docs). --quick: the Cornell box alone, small images, few frames (CI).\n";
    default:
        return "usage: voxatlas [view] [SCENE] [--mode direct|voxel|atlas|vpl] [--width W --height H]\n"
               "        [--camera ...] [--light ...] [--frames N] [--screenshot F.png]\n"
               "        [--hdr F.exr|F.pfm] [--keys \"FRAME:KEY,...\"] [--drop FRAME:FILE ...]\n"
               "        [--move DX,DY,DZ [--move-frames N]] [--exposure auto|EV]\n"
               "        [--tonemap none|filmic] [--set key=value ...]\n"
               "       voxatlas render SCENE --out F.png ...   (voxatlas render --help)\n"
               "       voxatlas bench [--scene ...] [--sweep smoke|quick|full] [--out-dir DIR]\n"
               "       voxatlas bench --suite quick|full   (the accuracy scoreboard)\n"
               "       voxatlas bench --temporal [--quick]   (flicker and trails)\n"
               "       voxatlas info SCENE [--set key=value ...]\n"
               "SCENE defaults to the Cornell box; --mode picks the GI mode the viewer starts in\n"
               "(voxel unless given; keys 1-4 switch). Without a display, view renders a headless\n"
               "screenshot instead.\n"
               "The viewer starts at --exposure auto --tonemap filmic (keys - = X T change them).\n"
               "Scripted runs (--frames N): --keys presses keys, --drop opens a file as if it were\n"
               "dropped on the window, --move moves the camera by DX,DY,DZ metres each frame\n"
               "(for the first N frames with --move-frames), --screenshot and --hdr save the last\n"
               "frame (tone mapped PNG; linear radiance), and a closing line gives the median\n"
               "frame times, moving and still.\n"
               "\n"
               "--set keys of the viewer (render --help lists the others):\n" + viewSettingsHelp();
    }
}

} // namespace gi::app
