#include "app/ViewerSession.h"

#include "app/SceneSetup.h"

#include <filesystem>

namespace gi::app {

// The dropped file goes through loadScene and selectCamera as the file on the command line
// did, with that command line's lights and settings; only the camera choice (--camera) is
// left to the new file. Everything is built before anything is replaced, so a file that fails
// at any step leaves the old scene, renderer and camera as they were.
void ViewerSession::openScene(const std::string& path) {
    const std::string name = std::filesystem::path(path).filename().string();
    auto refuse = [&](const std::string& error) {
        // Loading errors name the file already; the renderer's do not.
        mOpenError = error.find(name) == std::string::npos ? name + ": " + error : error;
        viewerSay(mOpenError);
    };
    Config config = mConfig;
    config.scenePath = path;
    config.sceneGiven = true;
    config.cameraIndex = 0;
    config.cameraSpec.reset();

    auto scene = std::make_unique<scene::Scene>();
    std::string error;
    if (!loadScene(config, *scene, error)) return refuse(error);
    const glm::ivec2 size = glm::max(mWindow->framebufferSize(), glm::ivec2(1));
    scene::CameraView camera;
    if (!selectCamera(config, *scene, float(size.x) / float(size.y), camera, error)) {
        return refuse(error);
    }
    auto renderer = std::make_unique<render::FrameRenderer>();
    if (!renderer->init(*scene, mSettings, mShaders, error) || !renderer->setMode(mMode, error)) {
        return refuse(error);
    }

    // The old renderer refers to the old scene, so it goes first.
    mRenderer = std::move(renderer);
    mScene = std::move(scene);
    mCamera = FlyCamera(camera, mScene->bounds);
    mStartView = camera;
    mCameras = ViewerCameras(*mScene, 0);
    mScriptedOffset = glm::vec3(0.0f);
    mAnimationTime = config.animationTime;
    if (!render::outputAvailable(mOutput, mMode)) mOutput = render::OutputComponent::Final;
    mOpenError.clear();
    mWindow->setTitle("voxatlas - " + name);
    notify("opened " + name);
    viewerSay("opened " + path);
}

} // namespace gi::app
