// The cameras the viewer's C key cycles through: the file's own, then the default camera
// chosen from the geometry (scene/DefaultCamera.h; the file's only camera when it has none),
// and the --camera spec when one was given. Home returns to the one the viewer opened with.
#pragma once

#include "scene/Scene.h"

#include <string>
#include <vector>

namespace gi::app {

class ViewerCameras {
public:
    // `startIndex`: the camera the viewer opens with, or -1 for the --camera spec.
    ViewerCameras(const scene::Scene& scene, int startIndex);

    void next();
    void home();
    // The selected camera; null while the --camera spec is selected.
    [[nodiscard]] const scene::Camera* current() const;
    // "2/3 name", "3/3 default camera" or "--camera".
    [[nodiscard]] std::string label() const;

private:
    std::vector<scene::Camera> mCameras;
    int mStart = 0;
    int mIndex = 0;   // into mCameras, or -1 for the --camera spec
};

} // namespace gi::app
