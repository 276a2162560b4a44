#include "app/SceneSetup.h"

#include "scene/GltfLoader.h"
#include "scene/SceneDefaults.h"

#include <cstdio>

namespace gi::app {

bool loadScene(const Config& config, scene::Scene& scene, std::string& error) {
    std::vector<std::string> warnings;
    if (!scene::loadGltf(config.scenePath, scene, error, warnings)) return false;
    for (const std::string& warning : warnings) std::fprintf(stderr, "warning: %s\n", warning.c_str());
    // --light adds to the scene's lights, so the default light is only for scenes that have
    // none at all, counting the command line's.
    for (const scene::Light& light : config.extraLights) scene.lights.push_back(light);
    scene::addDefaults(scene);
    return true;
}

bool selectCamera(const Config& config, const scene::Scene& scene, float aspect,
        render::CameraView& camera, std::string& error) {
    if (config.cameraSpec) {
        camera = render::cameraLookAt(config.cameraSpec->eye, config.cameraSpec->target,
                glm::radians(config.cameraSpec->yfovDegrees), aspect, scene.bounds);
        return true;
    }
    if (config.cameraIndex >= int(scene.cameras.size())) {
        error = config.scenePath + ": --camera " + std::to_string(config.cameraIndex) +
                ": the scene has " + std::to_string(scene.cameras.size()) + " camera(s)";
        return false;
    }
    camera = render::cameraFromScene(scene.cameras[std::size_t(config.cameraIndex)], aspect,
            scene.bounds);
    return true;
}

} // namespace gi::app
