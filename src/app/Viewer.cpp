#include "app/Viewer.h"

#include "app/FlyCamera.h"
#include "app/HeadlessView.h"
#include "app/PlanChoice.h"
#include "app/SceneSetup.h"
#include "app/SettingHotkeys.h"
#include "app/Ui.h"
#include "app/ViewerCameras.h"
#include "app/ViewerExposure.h"
#include "gl/GpuProfiler.h"
#include "gl/Limits.h"
#include "gl/ShaderLibrary.h"
#include "platform/GlfwWindow.h"
#include "render/FrameRenderer.h"
#include "core/ImageIO.h"
#include "render/OutputCatalog.h"
#include "render/PresentPass.h"
#include "scene/Animation.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <memory>

namespace gi::app {
namespace {

constexpr int kDefaultWidth = 1280;
constexpr int kDefaultHeight = 720;
constexpr double kNoticeSeconds = 6.0;
constexpr float kMaxStepSeconds = 0.1f;   // a stalled frame does not fling the camera away

void say(const std::string& message) {
    std::fprintf(stderr, "voxatlas view: %s\n", message.c_str());
}

int fail(int status, const std::string& message) {
    say(message);
    return status;
}

// The GPU modes of render/OutputCatalog.h on the number keys 1, 2, ... in the table's order. A
// mode FrameRenderer cannot switch to answers with its reason and the mode stays as it was.
std::vector<std::pair<std::string, const render::ModeEntry*>> modeKeys() {
    std::vector<std::pair<std::string, const render::ModeEntry*>> keys;
    for (const render::ModeEntry& entry : render::modeCatalog()) {
        if (entry.gpu) keys.emplace_back(std::to_string(keys.size() + 1), &entry);
    }
    return keys;
}

std::string upper(std::string text) {
    std::transform(text.begin(), text.end(), text.begin(),
            [](unsigned char c) { return char(std::toupper(c)); });
    return text == "ESC" ? "ESCAPE" : text;
}

// F12 without --screenshot: the first voxatlas-<n>.png that does not exist yet.
std::string nextScreenshotPath() {
    for (int n = 1;; ++n) {
        const std::string path = "voxatlas-" + std::to_string(n) + ".png";
        std::error_code ec;
        if (!std::filesystem::exists(path, ec)) return path;
    }
}

class Viewer {
public:
    Viewer(const Config& config, std::unique_ptr<scene::Scene> scene,
            std::unique_ptr<platform::GlfwWindow> window, const scene::CameraView& camera);
    int run();

private:
    struct Hotkey {
        std::string key;
        std::string help;
        std::function<void()> action;
    };

    // Builds the renderer, the presenter and the overlay; false with one message.
    bool start(std::string& error);
    // Moves the camera and plays the animations by `seconds` of wall time.
    void advance(double seconds);
    // The overlay, and the settings its widgets changed.
    void drawOverlay(double seconds);
    void handleKey(const std::string& name);
    void selectMode(const render::ModeEntry& entry);
    void cycleOutput();
    // Applies a change to a copy of the settings; keeps it if the renderer accepts it.
    void changeSetting(const std::function<void(Settings&)>& change, const std::string& key);
    // Shows the camera mCameras selects (after C or Home).
    void showCamera();
    void reloadShaders();
    FlyInput readInput();
    UiFrame uiFrame(double frameMs) const;
    // The last frame as the window shows it (exposure and curve), for screenshots.
    core::Image shownFrame() const;
    bool writeScreenshot(const core::Image& image, const std::string& path);
    void notify(const std::string& message);
    std::string cameraLabel() const;
    // Distance from the camera to the coarsest cascade level's far corner (m).
    float coarsestReach() const;

    const Config& mConfig;
    std::unique_ptr<scene::Scene> mScene;
    // Declared before every GL object so the context outlives them all.
    std::unique_ptr<platform::GlfwWindow> mWindow;
    gl::ShaderLibrary mShaders;
    gl::GpuProfiler mProfiler;
    render::FrameRenderer mRenderer;
    render::PresentPass mPresent;
    Ui mUi;

    Settings mSettings;
    FlyCamera mCamera;
    const scene::CameraView mStartView;       // the view the viewer opened with
    ViewerCameras mCameras;
    ViewerExposure mExposure;
    double mAnimationTime = 0.0;              // seconds of the scene's animations played
    bool mAnimationPaused = false;
    render::GiMode mMode = render::GiMode::Direct;
    render::OutputComponent mOutput = render::OutputComponent::Final;
    std::vector<Hotkey> mHotkeys;
    bool mQuit = false;
    bool mScreenshotRequested = false;
    bool mLooking = false;
    glm::dvec2 mLastCursor{0.0};
    std::string mNotice;
    std::chrono::steady_clock::time_point mNoticeTime;
    std::string mShaderErrors;
};

Viewer::Viewer(const Config& config, std::unique_ptr<scene::Scene> scene,
        std::unique_ptr<platform::GlfwWindow> window, const scene::CameraView& camera)
    : mConfig(config), mScene(std::move(scene)), mWindow(std::move(window)),
      mSettings(config.settings), mCamera(camera, mScene->bounds), mStartView(camera),
      mCameras(*mScene, config.cameraSpec ? -1 : config.cameraIndex),
      mExposure(config.toneMapping), mAnimationTime(config.animationTime) {
    mHotkeys.push_back({"H", "show / hide this help", [this] { mUi.toggleHelp(); }});
    for (const auto& modeKey : modeKeys()) {
        const render::ModeEntry* entry = modeKey.second;
        mHotkeys.push_back({modeKey.first, entry->label, [this, entry] { selectMode(*entry); }});
    }
    mHotkeys.push_back({"O", "output: final / direct / indirect / debug views", [this] { cycleOutput(); }});
    if (scene::animationDuration(*mScene) > 0.0f) {
        mHotkeys.push_back({"P", "pause / play the scene's animations", [this] {
            mAnimationPaused = !mAnimationPaused;
            notify(mAnimationPaused ? "animation paused" : "animation playing");
        }});
    }
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

void Viewer::handleKey(const std::string& name) {
    const std::string key = upper(name);
    for (const Hotkey& hotkey : mHotkeys) {
        if (hotkey.key == key) {
            hotkey.action();
            return;
        }
    }
}

void Viewer::notify(const std::string& message) {
    mNotice = message;
    mNoticeTime = std::chrono::steady_clock::now();
}

void Viewer::selectMode(const render::ModeEntry& entry) {
    std::string error;
    if (!mRenderer.setMode(entry.mode, error)) {
        notify(error);
        say(error);
        return;
    }
    mMode = entry.mode;
    if (!render::outputAvailable(mOutput, mMode)) mOutput = render::OutputComponent::Final;
    notify(std::string("mode: ") + entry.label);
}

void Viewer::cycleOutput() {
    // Every output in the order of the name table; technique debug views show only while
    // their technique is active, so the cycle skips the other technique's views.
    const auto& outputs = render::allOutputComponents();
    auto current = std::find(outputs.begin(), outputs.end(), mOutput);
    for (std::size_t step = 1; step <= outputs.size(); ++step) {
        const render::OutputComponent next =
                outputs[(std::size_t(current - outputs.begin()) + step) % outputs.size()];
        if (render::outputAvailable(next, mMode)) {
            mOutput = next;
            break;
        }
    }
    notify(std::string("output: ") + render::outputComponentName(mOutput));
}

void Viewer::changeSetting(const std::function<void(Settings&)>& change, const std::string& key) {
    Settings candidate = settingsToStep(mSettings, mRenderer.effectiveSettings(), key);
    change(candidate);
    std::string error;
    if (!mRenderer.setSettings(candidate, error)) {
        notify(error);
        say(error);
        return;
    }
    mSettings = candidate;
    for (const SettingSpec& spec : settingSpecs()) {
        if (spec.key == key) notify(key + " = " + spec.get(mSettings));
    }
}

float Viewer::coarsestReach() const {
    const gi::GiTechnique* technique = mRenderer.technique();
    if (technique && technique->gatherReach() > 0.0f) return technique->gatherReach();
    return 2.0f * glm::length(mScene->bounds.size());
}

void Viewer::showCamera() {
    const glm::ivec2 size = glm::max(mWindow->framebufferSize(), glm::ivec2(1));
    const scene::Camera* camera = mCameras.current();
    mCamera.reset(camera ? scene::cameraFromScene(*camera, float(size.x) / float(size.y),
                                   mScene->bounds)
                         : mStartView);
    notify("camera " + cameraLabel());
}

void Viewer::reloadShaders() {
    std::string errors;
    if (mShaders.reloadAll(errors)) {
        mShaderErrors.clear();
        notify("shaders reloaded");
        return;
    }
    mShaderErrors = errors;
    notify("shader reload failed; the previous programs stay in use");
    std::fprintf(stderr,
            "voxatlas view: shader reload failed, keeping the previous programs:\n%s\n",
            errors.c_str());
}

std::string Viewer::cameraLabel() const {
    return mCamera.atStart() ? mCameras.label() : mCameras.label() + " (moved)";
}

FlyInput Viewer::readInput() {
    FlyInput input;
    if (!mUi.wantsKeyboard()) {
        input.forward = mWindow->keyDown(GLFW_KEY_W);
        input.back = mWindow->keyDown(GLFW_KEY_S);
        input.left = mWindow->keyDown(GLFW_KEY_A);
        input.right = mWindow->keyDown(GLFW_KEY_D);
        input.down = mWindow->keyDown(GLFW_KEY_Q);
        input.up = mWindow->keyDown(GLFW_KEY_E);
        input.fast =
                mWindow->keyDown(GLFW_KEY_LEFT_SHIFT) || mWindow->keyDown(GLFW_KEY_RIGHT_SHIFT);
    }
    const bool held = mWindow->mouseButtonDown(GLFW_MOUSE_BUTTON_RIGHT) ||
                      mWindow->mouseButtonDown(GLFW_MOUSE_BUTTON_LEFT);
    const glm::dvec2 cursor = mWindow->cursorPosition();
    // A drag that starts on the overlay belongs to the overlay for its whole length.
    if (held && !mLooking && !mUi.wantsMouse()) {
        mLooking = true;
        mLastCursor = cursor;
    }
    if (!held) mLooking = false;
    input.look = mLooking;
    input.mouseDelta = mLooking ? glm::vec2(cursor - mLastCursor) : glm::vec2(0.0f);
    mLastCursor = cursor;
    const double scroll = mWindow->takeScroll();
    input.scrollSteps = mUi.wantsMouse() ? 0.0f : float(scroll);
    return input;
}

UiFrame Viewer::uiFrame(double frameMs) const {
    UiFrame frame;
    frame.frameMs = frameMs;
    frame.timings = mProfiler.timings();
    frame.memory = mRenderer.memory();
    frame.mode = render::modeEntry(mMode).label;
    if (const GiTechnique* technique = mRenderer.technique()) frame.giStatus = technique->status();
    frame.plan = render::describePlan(mRenderer.plan());
    frame.output = render::outputComponentName(mOutput);
    frame.exposure = mExposure.label();
    frame.camera = cameraLabel();
    frame.triangles = mScene->triangleCount();
    frame.framebufferSize = mWindow->framebufferSize();
    frame.vsync = mWindow->vsync();
    frame.speed = mCamera.speed();
    const double age = std::chrono::duration<double>(std::chrono::steady_clock::now() -
                                                     mNoticeTime).count();
    if (age < kNoticeSeconds) frame.notice = mNotice;
    frame.shaderErrors = mShaderErrors;
    return frame;
}

core::Image Viewer::shownFrame() const {
    const core::Image image = mRenderer.readback();
    return render::isRadiometric(mOutput) ? mExposure.shown(image) : image;
}

bool Viewer::writeScreenshot(const core::Image& image, const std::string& path) {
    std::string error;
    if (!core::writePng(path, image, error)) {
        notify("screenshot failed: " + error);
        say(error);
        return false;
    }
    notify("screenshot: " + path);
    say("wrote " + path + " (" + std::to_string(image.width) + "x" +
            std::to_string(image.height) + ")");
    return true;
}

bool Viewer::start(std::string& error) {
    if (!mRenderer.init(*mScene, mSettings, mShaders, error)) return false;
    if (mConfig.mode != mMode) {
        if (!mRenderer.setMode(mConfig.mode, error)) return false;
        mMode = mConfig.mode;
    }
    if (!mPresent.init(mShaders, error)) return false;
    if (!mUi.init(*mWindow, error)) return false;
    std::vector<HotkeyHelp> help = {{"W A S D", "move"}, {"Q / E", "down / up"},
            {"Shift", "move x4 faster"}, {"mouse drag", "look around (right or left button)"},
            {"wheel", "movement speed"}};
    for (const Hotkey& hotkey : mHotkeys) {
        help.push_back({hotkey.key == "ESCAPE" ? "Esc" : hotkey.key, hotkey.help});
    }
    mUi.setHotkeys(std::move(help));
    // Scripted runs go as fast as they can; interactive ones follow the display.
    mWindow->setVsync(mConfig.frames == 0);
    for (const KeyEvent& event : mConfig.keys) {
        if (mConfig.frames > 0 && event.frame >= mConfig.frames) {
            say("--keys " + std::to_string(event.frame) + ":" + event.key +
                    " is after the last frame (--frames " + std::to_string(mConfig.frames) +
                    ", counted from 0) and will not fire");
        }
    }
    return true;
}

void Viewer::advance(double seconds) {
    mCamera.update(readInput(), std::min(float(seconds), kMaxStepSeconds));
    if (!mAnimationPaused && mRenderer.gpuScene().hasDynamicGeometry()) {
        // Scripted runs (--frames) advance by a fixed 1/30 s so screenshots repeat.
        mAnimationTime += mConfig.frames > 0 ? 1.0 / 30.0 : std::min(seconds, 0.25);
        scene::poseScene(*mScene, mAnimationTime);
        mRenderer.setPose(*mScene);
    }
}

void Viewer::drawOverlay(double seconds) {
    if (mUi.draw(uiFrame(seconds * 1000.0), mSettings, mProfiler)) {
        std::string error;
        if (!mRenderer.setSettings(mSettings, error)) {
            notify(error);
            say(error);
        }
    }
}

int Viewer::run() {
    std::string error;
    if (!start(error)) return fail(1, error);
    using Clock = std::chrono::steady_clock;
    Clock::time_point previous = Clock::now();
    bool rendered = false, finalWritten = false;
    for (int frame = 0; mConfig.frames == 0 || frame < mConfig.frames; ++frame) {
        mWindow->pollEvents();
        for (int key : mWindow->takeKeyPresses()) {
            if (!mUi.wantsKeyboard()) handleKey(platform::keyName(key));
        }
        for (const KeyEvent& event : mConfig.keys) {
            if (event.frame == frame) handleKey(event.key);
        }
        if (mQuit || mWindow->shouldClose()) break;

        const Clock::time_point now = Clock::now();
        const double seconds = std::chrono::duration<double>(now - previous).count();
        previous = now;
        advance(seconds);

        const glm::ivec2 size = mWindow->framebufferSize();
        if (size.x <= 0 || size.y <= 0) {
            mWindow->waitEvents(0.1);
            continue;
        }
        mRenderer.render(mCamera.view(float(size.x) / float(size.y)), size, mOutput, mProfiler);
        // Debug views (albedo, normals, ...) are shown as they are; radiance is exposed.
        const bool exposed = render::isRadiometric(mOutput);
        // Scripted runs adapt by a fixed 1/30 s a frame, as they animate, so screenshots repeat.
        if (exposed) mExposure.meter(mRenderer, mConfig.frames > 0 ? 1.0 / 30.0 : seconds);
        mPresent.execute({mRenderer.radiance(), mRenderer.radianceScale(),
                                 exposed ? mExposure.exposure() : 1.0f,
                                 exposed ? mExposure.curve() : core::ToneCurve::None},
                {size}, mProfiler);
        rendered = true;
        // Screenshots are taken before the overlay is drawn (view.screenshot_ui aside).
        if (mScreenshotRequested) {
            mScreenshotRequested = false;
            const std::string path =
                    mConfig.screenshotPath.empty() ? nextScreenshotPath() : mConfig.screenshotPath;
            (void)writeScreenshot(shownFrame(), path);
        }
        drawOverlay(seconds);
        const bool lastFrame = mConfig.frames > 0 && frame + 1 == mConfig.frames;
        if (lastFrame && mSettings.screenshotUi && !mConfig.screenshotPath.empty()) {
            finalWritten = true;
            if (!writeScreenshot(render::PresentPass::readDefaultFramebuffer(size),
                        mConfig.screenshotPath)) {
                return 1;
            }
        }
        mWindow->swapBuffers();
        mProfiler.collect();
    }

    if (!mConfig.screenshotPath.empty() && !finalWritten) {
        if (!rendered) {
            return fail(1, "no frame was rendered, so " + mConfig.screenshotPath +
                    " was not written");
        }
        if (!writeScreenshot(shownFrame(), mConfig.screenshotPath)) return 1;
    }
    if (const GLenum glError = glGetError(); glError != GL_NO_ERROR) {
        return fail(1, gl::glErrorName(glError) + " during the session");
    }
    return 0;
}

} // namespace

int runViewer(const Config& config) {
    std::string error;
    if (!config.screenshotPath.empty() && !core::checkWritable(config.screenshotPath, error)) {
        return fail(2, error);
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
    Viewer viewer(config, std::move(scene), std::move(window), camera);
    return viewer.run();
}

} // namespace gi::app
