#include "app/ViewerCameras.h"

#include "reference/EmbreeRayCaster.h"

#include <algorithm>

namespace gi::app {

ViewerCameras::ViewerCameras(const scene::Scene& scene, int startIndex)
    : mCameras(scene.cameras), mStart(startIndex), mIndex(startIndex) {
    const bool hasDefault = std::any_of(mCameras.begin(), mCameras.end(),
            [](const scene::Camera& camera) { return camera.isDefault; });
    if (!hasDefault) mCameras.push_back(reference::defaultCameraFromGeometry(scene));
}

void ViewerCameras::next() {
    // The --camera spec joins the cycle after the last camera.
    const int count = int(mCameras.size()) + (mStart < 0 ? 1 : 0);
    mIndex = (mIndex + 1) % count;
    if (mIndex == int(mCameras.size())) mIndex = -1;
}

void ViewerCameras::home() { mIndex = mStart; }

const scene::Camera* ViewerCameras::current() const {
    return mIndex >= 0 ? &mCameras[std::size_t(mIndex)] : nullptr;
}

std::string ViewerCameras::label() const {
    if (mIndex < 0) return "--camera";
    const scene::Camera& camera = mCameras[std::size_t(mIndex)];
    std::string label = std::to_string(mIndex + 1) + "/" + std::to_string(mCameras.size());
    return camera.name.empty() ? label : label + " " + camera.name;
}

} // namespace gi::app
