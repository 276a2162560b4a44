#include "app/ViewerSession.h"

#include "app/SettingHotkeys.h"
#include "gl/Limits.h"
#include "scene/Animation.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <filesystem>

namespace gi::app {
namespace {

constexpr float kMaxStepSeconds = 0.1f;   // a stalled frame does not fling the camera away
constexpr float kDefaultBudgetMs = 100.0f;   // what B turns on when the budget started off

// The GPU modes of render/OutputCatalog.h on the number keys 1, 2, ... in the table's order. A
// mode FrameRenderer cannot switch to answers with its reason and the mode stays as it was.
std::vector<std::pair<std::string, const render::ModeEntry*>> modeKeys() {
    std::vector<std::pair<std::string, const render::ModeEntry*>> keys;
    for (const render::ModeEntry& entry : render::modeCatalog()) {
        if (entry.gpu) keys.emplace_back(std::to_string(keys.size() + 1), &entry);
    }
    return keys;
}

// F12 without --screenshot: the first voxatlas-<n>.png that does not exist yet.
std::string nextScreenshotPath() {
    for (int n = 1;; ++n) {
        const std::string path = "voxatlas-" + std::to_string(n) + ".png";
        std::error_code ec;
        if (!std::filesystem::exists(path, ec)) return path;
    }
}

int fail(int status, const std::string& message) {
    viewerSay(message);
    return status;
}

double millisecondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
            .count();
}

} // namespace

void viewerSay(const std::string& message) {
    std::fprintf(stderr, "voxatlas view: %s\n", message.c_str());
}

ViewerSession::ViewerSession(const Config& config, std::unique_ptr<scene::Scene> scene,
        std::unique_ptr<platform::GlfwWindow> window, const scene::CameraView& camera)
    : mConfig(config), mScene(std::move(scene)), mWindow(std::move(window)),
      mRenderer(std::make_unique<render::FrameRenderer>()), mSettings(config.settings),
      mCamera(camera, mScene->bounds), mStartView(camera),
      mCameras(*mScene, config.cameraSpec ? -1 : config.cameraIndex),
      mExposure(config.toneMapping), mResolution(config.settings.frameBudgetMs),
      mBudgetWhenOff(config.settings.frameBudgetMs > 0.0f ? config.settings.frameBudgetMs
                                                          : kDefaultBudgetMs),
      mAnimationTime(config.animationTime) {
    addHotkeys();
}

void ViewerSession::addHotkeys() {
    mHotkeys.push_back({"H", "show / hide this help", [this] { mUi.toggleHelp(); }});
    for (const auto& modeKey : modeKeys()) {
        const render::ModeEntry* entry = modeKey.second;
        mHotkeys.push_back({modeKey.first, entry->label, [this, entry] { selectMode(*entry); }});
    }
    mHotkeys.push_back({"O", "output: final / direct / indirect / debug views",
            [this] { cycleOutput(); }});
    mHotkeys.push_back({"P", "pause / play the scene's animations (if it has any)", [this] {
        if (scene::animationDuration(*mScene) <= 0.0f) return notify("the scene has no animations");
        mAnimationPaused = !mAnimationPaused;
        notify(mAnimationPaused ? "animation paused" : "animation playing");
    }});
    for (const SettingHotkey& hotkey : settingHotkeys()) {
        mHotkeys.push_back({hotkey.key, hotkey.help, [this, &hotkey] {
            const float reach = coarsestReach();
            changeSetting([&](Settings& s) { hotkey.step(s, reach); }, hotkey.setting);
        }});
    }
    for (const ViewerExposure::Hotkey& key : ViewerExposure::hotkeys()) {
        mHotkeys.push_back(
                {key.key, key.help, [this, &key] { notify((mExposure.*key.action)()); }});
    }
    mHotkeys.push_back({"B", "frame budget on / off (off: always full resolution)",
            [this] { toggleBudget(); }});
    mHotkeys.push_back({"C", "next camera: the file's, then the default one",
            [this] { mCameras.next(); showCamera(); }});
    mHotkeys.push_back({"HOME", "back to the start camera",
            [this] { mCameras.home(); showCamera(); }});
    mHotkeys.push_back({"V", "vsync on / off", [this] {
        mWindow->setVsync(!mWindow->vsync());
        notify(std::string("vsync ") + (mWindow->vsync() ? "on" : "off"));
    }});
    mHotkeys.push_back({"R", "reload shaders", [this] { reloadShaders(); }});
    mHotkeys.push_back({"F12", "screenshot (without the overlay)",
            [this] { mScreenshotRequested = true; }});
    mHotkeys.push_back({"ESCAPE", "quit", [this] { mQuit = true; }});
}

bool ViewerSession::start(std::string& error) {
    if (!mRenderer->init(*mScene, mSettings, mShaders, error)) return false;
    if (mConfig.mode != mMode) {
        if (!mRenderer->setMode(mConfig.mode, error)) return false;
        mMode = mConfig.mode;
    }
    if (!mPresent.init(mShaders, error)) return false;
    if (!mUi.init(*mWindow, error)) return false;
    std::vector<HotkeyHelp> help = {{"W A S D", "move"}, {"Q / E", "down / up"},
            {"Shift", "move x4 faster"}, {"mouse drag", "look around (right or left button)"},
            {"wheel", "movement speed"}, {"drop a file", "open a .gltf / .glb scene"}};
    for (const Hotkey& hotkey : mHotkeys) {
        help.push_back({hotkey.key == "ESCAPE" ? "Esc" : hotkey.key, hotkey.help});
    }
    mUi.setHotkeys(std::move(help));
    // Scripted runs go as fast as they can; interactive ones follow the display.
    mWindow->setVsync(mConfig.frames == 0);
    auto warnLate = [&](int frame, const std::string& what) {
        if (mConfig.frames > 0 && frame >= mConfig.frames) {
            viewerSay(what + " is after the last frame (--frames " +
                    std::to_string(mConfig.frames) + ", counted from 0) and will not happen");
        }
    };
    for (const KeyEvent& event : mConfig.keys) {
        warnLate(event.frame, "--keys " + std::to_string(event.frame) + ":" + event.key);
    }
    for (const DropEvent& drop : mConfig.drops) {
        warnLate(drop.frame, "--drop " + std::to_string(drop.frame) + ":" + drop.path);
    }
    return true;
}

void ViewerSession::handleEvents(int frame) {
    mWindow->pollEvents();
    for (int key : mWindow->takeKeyPresses()) {
        if (!mUi.wantsKeyboard()) handleKey(platform::keyName(key));
    }
    for (const KeyEvent& event : mConfig.keys) {
        if (event.frame == frame) handleKey(event.key);
    }
    const std::vector<std::string> dropped = mWindow->takeDroppedPaths();
    if (!dropped.empty()) {
        if (dropped.size() > 1) {
            notify(std::to_string(dropped.size()) + " files dropped; opening the first");
        }
        openScene(dropped.front());
    }
    for (const DropEvent& drop : mConfig.drops) {
        if (drop.frame == frame) openScene(drop.path);
    }
}

void ViewerSession::advance(double seconds, int frame) {
    mCamera.update(readInput(), std::min(float(seconds), kMaxStepSeconds));
    // --move: frame f shows the camera moved by min(f, --move-frames) steps.
    if (frame > 0 && (mConfig.moveFrames == 0 || frame <= mConfig.moveFrames)) {
        mScriptedOffset += mConfig.cameraMove;
    }
    if (!mAnimationPaused && mRenderer->gpuScene().hasDynamicGeometry()) {
        // Scripted runs (--frames) advance by a fixed 1/30 s so screenshots repeat.
        mAnimationTime += mConfig.frames > 0 ? 1.0 / 30.0 : std::min(seconds, 0.25);
        scene::poseScene(*mScene, mAnimationTime);
        mRenderer->setPose(*mScene);
    }
}

scene::CameraView ViewerSession::currentView(float aspect) const {
    scene::CameraView view = mCamera.view(aspect);
    if (mScriptedOffset != glm::vec3(0.0f)) {
        view.eye += mScriptedOffset;
        view.view = view.view * glm::translate(glm::mat4(1.0f), -mScriptedOffset);
    }
    return view;
}

void ViewerSession::renderFrame(glm::ivec2 windowSize, bool fullResolution, double seconds) {
    mResolution.setBudget(mSettings.frameBudgetMs);
    const scene::CameraView view = currentView(float(windowSize.x) / float(windowSize.y));
    const glm::mat4 viewProjection = view.viewProjection();
    const bool changed = mLastViewProjection && viewProjection != *mLastViewProjection;
    mLastViewProjection = viewProjection;
    const float scale = mResolution.beginFrame(changed, fullResolution);
    mInternalSize = ResolutionController::scaledSize(windowSize, scale);
    mRenderer->render(view, mInternalSize, mOutput, mProfiler);
    // Debug views (albedo, normals, ...) are shown as they are; radiance is exposed.
    const bool exposed = render::isRadiometric(mOutput);
    // Scripted runs adapt by a fixed 1/30 s a frame, as they animate, so screenshots repeat.
    if (exposed) mExposure.meter(*mRenderer, mConfig.frames > 0 ? 1.0 / 30.0 : seconds);
    mPresent.execute({mRenderer->radiance(), mRenderer->radianceScale(),
                             exposed ? mExposure.exposure() : 1.0f,
                             exposed ? mExposure.curve() : core::ToneCurve::None},
            {windowSize}, mProfiler);
}

int ViewerSession::run() {
    std::string error;
    if (!start(error)) return fail(1, error);
    using Clock = std::chrono::steady_clock;
    Clock::time_point previous = Clock::now();
    bool rendered = false, finalWritten = false;
    const bool finalImage = !mConfig.screenshotPath.empty() || !mConfig.hdrPath.empty();
    for (int frame = 0; mConfig.frames == 0 || frame < mConfig.frames; ++frame) {
        handleEvents(frame);
        if (mQuit || mWindow->shouldClose()) break;

        const Clock::time_point now = Clock::now();
        const double seconds = std::chrono::duration<double>(now - previous).count();
        previous = now;
        advance(seconds, frame);

        const glm::ivec2 size = mWindow->framebufferSize();
        if (size.x <= 0 || size.y <= 0) {
            mWindow->waitEvents(0.1);
            continue;
        }
        const bool lastFrame = mConfig.frames > 0 && frame + 1 == mConfig.frames;
        // Screenshots show the full resolution, whatever the budget chose for the frame.
        renderFrame(size, mScreenshotRequested || (lastFrame && finalImage), seconds);
        rendered = true;
        // Screenshots are taken before the overlay is drawn (view.screenshot_ui aside).
        if (mScreenshotRequested) {
            mScreenshotRequested = false;
            const std::string path =
                    mConfig.screenshotPath.empty() ? nextScreenshotPath() : mConfig.screenshotPath;
            (void)writeScreenshot(shownFrame(), path);
        }
        drawOverlay(seconds);
        if (lastFrame && mSettings.screenshotUi && !mConfig.screenshotPath.empty()) {
            finalWritten = true;
            if (!writeScreenshot(render::PresentPass::readDefaultFramebuffer(size),
                        mConfig.screenshotPath)) {
                return 1;
            }
        }
        mWindow->swapBuffers();
        mProfiler.collect();
        const double frameMs = millisecondsSince(now);
        mResolution.endFrame(frameMs);
        mFrameLog.record(frameMs, mResolution.moving(), mInternalSize);
    }

    if (mConfig.frames > 0 && rendered) {
        char budget[48];
        std::snprintf(budget, sizeof budget, "%g ms", double(mSettings.frameBudgetMs));
        viewerSay("frame times (budget " + std::string(mSettings.frameBudgetMs > 0.0f
                                                   ? budget : "off") + "): " +
                mFrameLog.summary());
    }
    if (finalImage && !rendered) {
        return fail(1, "no frame was rendered, so " +
                (mConfig.screenshotPath.empty() ? mConfig.hdrPath : mConfig.screenshotPath) +
                " was not written");
    }
    if (!mConfig.screenshotPath.empty() && !finalWritten &&
            !writeScreenshot(shownFrame(), mConfig.screenshotPath)) {
        return 1;
    }
    if (!mConfig.hdrPath.empty() && !writeHdrFrame()) return 1;
    if (const GLenum glError = glGetError(); glError != GL_NO_ERROR) {
        return fail(1, gl::glErrorName(glError) + " during the session");
    }
    return 0;
}

} // namespace gi::app
