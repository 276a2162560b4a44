#include "app/SceneSetup.h"

#include "reference/EmbreeRayCaster.h"
#include "scene/Animation.h"
#include "scene/EmissionLights.h"
#include "scene/GltfLoader.h"
#include "scene/Recentre.h"

#include <cstdio>

namespace gi::app {
namespace {

// Emitting area, as a share of all surface area, from which emissive surfaces are taken to
// light the scene by themselves (an emissive ceiling panel of a Cornell box: 0.7%).
constexpr double kEmittingShareThatLights = 1e-3;

} // namespace

bool loadScene(const Config& config, scene::Scene& scene, std::string& error,
        scene::DefaultsReport* report) {
    std::vector<std::string> warnings;
    if (!scene::loadGltf(config.scenePath, scene, error, warnings)) return false;
    for (const std::string& warning : warnings) std::fprintf(stderr, "warning: %s\n", warning.c_str());
    scene.origin = scene::recentreFarScene(scene);
    scene::poseScene(scene, config.animationTime);
    if (scene.origin != glm::vec3(0.0f)) {
        std::fprintf(stderr, "note: %s lies far from the origin; it is rendered moved by "
                "(%g, %g, %g) m to keep float precision\n", config.scenePath.c_str(),
                -scene.origin.x, -scene.origin.y, -scene.origin.z);
    }
    // --light adds to the scene's lights, so the default light is only for scenes that have
    // none at all, counting the command line's. --light none drops the scene's lights and the
    // default one, keeping only the command line's (a dark scene is a legitimate test case).
    if (config.noLights) scene.lights.clear();
    // Command-line positions are in the file's coordinates.
    for (scene::Light light : config.extraLights) {
        light.position -= scene.origin;
        for (scene::EmitterTriangle& t : light.emitters) {
            t.p0 -= scene.origin;
            t.p1 -= scene.origin;
            t.p2 -= scene.origin;
        }
        scene.lights.push_back(light);
    }
    // Emissive surfaces are lights (scene/EmissionLights.h); they are geometry, so --light none
    // keeps them. Emitters covering less than kEmittingShareThatLights of the surface light
    // only their surroundings: such a scene also gets the default light, chosen as if it
    // had no lights at all.
    const scene::EmissionLightsReport emission = scene::addEmissionLights(scene);
    const bool emittersLightScene = emission.emittingAreaShare >= kEmittingShareThatLights;
    std::vector<scene::Light> weakEmitters;
    if (emission.lights > 0 && !emittersLightScene) {
        weakEmitters.assign(scene.lights.end() - std::ptrdiff_t(emission.lights), scene.lights.end());
        scene.lights.resize(scene.lights.size() - emission.lights);
    }
    std::string warning;
    scene::DefaultsReport defaults = reference::addDefaultsFromGeometry(scene, warning);
    if (!warning.empty()) std::fprintf(stderr, "warning: %s\n", warning.c_str());
    scene.lights.insert(scene.lights.end(), weakEmitters.begin(), weakEmitters.end());
    if (emission.lights > 0) {
        const std::string what = "emissive surfaces: " + emission.summary;
        defaults.lights = emittersLightScene || defaults.lights.empty()
                ? what : what + ", too small to light the scene; " + defaults.lights;
    }
    if (config.noLights) {
        std::erase_if(scene.lights, [](const scene::Light& light) { return light.isDefault; });
        defaults.lights.clear();
    }
    if (report) *report = defaults;
    return true;
}

bool selectCamera(const Config& config, const scene::Scene& scene, float aspect,
        scene::CameraView& camera, std::string& error) {
    if (config.cameraSpec) {
        camera = scene::cameraLookAt(config.cameraSpec->eye - scene.origin,
                config.cameraSpec->target - scene.origin,
                glm::radians(config.cameraSpec->yfovDegrees), aspect, scene.bounds);
        return true;
    }
    if (config.cameraIndex >= int(scene.cameras.size())) {
        error = config.scenePath + ": --camera " + std::to_string(config.cameraIndex) +
                ": the scene has " + std::to_string(scene.cameras.size()) + " camera(s)";
        return false;
    }
    camera = scene::cameraFromScene(scene.cameras[std::size_t(config.cameraIndex)], aspect,
            scene.bounds);
    return true;
}

} // namespace gi::app
