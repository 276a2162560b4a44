#include "app/Viewer.h"

#include "app/HeadlessView.h"
#include "app/SceneSetup.h"
#include "app/ViewerSession.h"
#include "core/ImageIO.h"
#include "platform/GlfwWindow.h"

#include <filesystem>
#include <memory>

namespace gi::app {
namespace {

constexpr int kDefaultWidth = 1280;
constexpr int kDefaultHeight = 720;

int fail(int status, const std::string& message) {
    viewerSay(message);
    return status;
}

} // namespace

int runViewer(const Config& config) {
    std::string error;
    for (const std::string* path : {&config.screenshotPath, &config.hdrPath}) {
        if (!path->empty() && !core::checkWritable(*path, error)) return fail(2, error);
    }
    for (const KeyEvent& event : config.keys) {
        if (platform::keyFromName(event.key) < 0) {
            return fail(2, "--keys: unknown key '" + event.key +
                    "' (names like H, 1, F12, ESCAPE)");
        }
    }

    auto scene = std::make_unique<scene::Scene>();
    if (!loadScene(config, *scene, error)) return fail(2, error);
    const int width = config.width > 0 ? config.width : kDefaultWidth;
    const int height = config.height > 0 ? config.height : kDefaultHeight;
    scene::CameraView camera;
    if (!selectCamera(config, *scene, float(width) / float(height), camera, error)) {
        return fail(2, error);
    }

    platform::WindowOptions options;
    options.title = "voxatlas - " + std::filesystem::path(config.scenePath).filename().string();
    options.width = width;
    options.height = height;
    options.debugContext = config.settings.glDebug;
    platform::WindowFailure failure = platform::WindowFailure::None;
    auto window = platform::GlfwWindow::create(options, failure, error);
    if (!window) {
        if (failure != platform::WindowFailure::NoDisplay) return fail(1, error);
        scene.reset();
        return runHeadlessView(config, {width, height}, error);
    }
    ViewerSession viewer(config, std::move(scene), std::move(window), camera);
    return viewer.run();
}

} // namespace gi::app
