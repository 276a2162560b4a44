// What every command does with a scene before rendering: load and validate it, add the
// documented default light and camera where the file has none, append --light lights, and
// pick the camera the command asked for.
#pragma once

#include "app/CommandLine.h"
#include "scene/CameraView.h"
#include "scene/Scene.h"
#include "scene/SceneDefaults.h"

#include <string>

namespace gi::app {

// Loads config.scenePath; warnings go to stderr. Errors are one line naming the file.
// `report`, when given, receives why each default light or camera was chosen.
[[nodiscard]] bool loadScene(const Config& config, scene::Scene& scene, std::string& error,
        scene::DefaultsReport* report = nullptr);

// The --camera index or spec, for an output of the given aspect ratio.
[[nodiscard]] bool selectCamera(const Config& config, const scene::Scene& scene, float aspect,
        scene::CameraView& camera, std::string& error);

} // namespace gi::app
