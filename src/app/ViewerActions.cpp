#include "app/ViewerSession.h"

#include "core/ImageIO.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <algorithm>
#include <cctype>
#include <cstdio>

namespace gi::app {
namespace {

constexpr double kNoticeSeconds = 6.0;

std::string upper(std::string text) {
    std::transform(text.begin(), text.end(), text.begin(),
            [](unsigned char c) { return char(std::toupper(c)); });
    return text == "ESC" ? "ESCAPE" : text;
}

} // namespace

void ViewerSession::handleKey(const std::string& name) {
    const std::string key = upper(name);
    for (const Hotkey& hotkey : mHotkeys) {
        if (hotkey.key == key) {
            hotkey.action();
            return;
        }
    }
}

void ViewerSession::notify(const std::string& message) {
    mNotice = message;
    mNoticeTime = std::chrono::steady_clock::now();
}

void ViewerSession::selectMode(const render::ModeEntry& entry) {
    std::string error;
    if (!mRenderer->setMode(entry.mode, error)) {
        notify(error);
        viewerSay(error);
        return;
    }
    mMode = entry.mode;
    if (!render::outputAvailable(mOutput, mMode)) mOutput = render::OutputComponent::Final;
    notify(std::string("mode: ") + entry.label);
}

void ViewerSession::cycleOutput() {
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

void ViewerSession::toggleBudget() {
    if (mSettings.frameBudgetMs > 0.0f) {
        mBudgetWhenOff = mSettings.frameBudgetMs;
        mSettings.frameBudgetMs = 0.0f;
        notify("frame budget off: every frame at full resolution");
        return;
    }
    mSettings.frameBudgetMs = mBudgetWhenOff;
    char text[64];
    std::snprintf(text, sizeof text, "frame budget %g ms", double(mSettings.frameBudgetMs));
    notify(text);
}

void ViewerSession::changeSetting(const std::function<void(Settings&)>& change,
        const std::string& key) {
    Settings candidate = settingsToStep(mSettings, mRenderer->effectiveSettings(), key);
    change(candidate);
    std::string error;
    if (!mRenderer->setSettings(candidate, error)) {
        notify(error);
        viewerSay(error);
        return;
    }
    mSettings = candidate;
    for (const SettingSpec& spec : settingSpecs()) {
        if (spec.key == key) notify(key + " = " + spec.get(mSettings));
    }
}

float ViewerSession::coarsestReach() const {
    const gi::GiTechnique* technique = mRenderer->technique();
    if (technique && technique->gatherReach() > 0.0f) return technique->gatherReach();
    return 2.0f * glm::length(mScene->bounds.size());
}

void ViewerSession::showCamera() {
    const glm::ivec2 size = glm::max(mWindow->framebufferSize(), glm::ivec2(1));
    const scene::Camera* camera = mCameras.current();
    mCamera.reset(camera ? scene::cameraFromScene(*camera, float(size.x) / float(size.y),
                                   mScene->bounds)
                         : mStartView);
    notify("camera " + cameraLabel());
}

void ViewerSession::reloadShaders() {
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

std::string ViewerSession::cameraLabel() const {
    return mCamera.atStart() ? mCameras.label() : mCameras.label() + " (moved)";
}

FlyInput ViewerSession::readInput() {
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

UiFrame ViewerSession::uiFrame(double frameMs) const {
    UiFrame frame;
    frame.frameMs = frameMs;
    frame.timings = mProfiler.timings();
    frame.memory = mRenderer->memory();
    frame.mode = render::modeEntry(mMode).label;
    if (const GiTechnique* technique = mRenderer->technique()) {
        const auto vpl = mRenderer->vplReport();
        // A refused setting (an octree over its budget) says why instead.
        frame.giStatus = vpl && technique->failure().empty()
                                 ? vpl::describeVpl(*vpl, frame.timings)
                                 : technique->status();
    }
    frame.shadowStatus = render::describeShadowMethod(mRenderer->shadowReport());
    frame.plan = render::describePlan(mRenderer->plan());
    frame.output = render::outputComponentName(mOutput);
    frame.exposure = mExposure.label();
    frame.camera = cameraLabel();
    frame.triangles = mScene->triangleCount();
    frame.framebufferSize = mWindow->framebufferSize();
    frame.renderSize = mInternalSize;
    frame.budgetMs = mSettings.frameBudgetMs;
    frame.reduced = mResolution.moving();
    frame.vsync = mWindow->vsync();
    frame.speed = mCamera.speed();
    const double age = std::chrono::duration<double>(std::chrono::steady_clock::now() -
                                                     mNoticeTime).count();
    if (age < kNoticeSeconds) frame.notice = mNotice;
    frame.shaderErrors = mShaderErrors;
    frame.openError = mOpenError;
    return frame;
}

core::Image ViewerSession::shownFrame() const {
    const core::Image image = mRenderer->readback();
    return render::isRadiometric(mOutput) ? mExposure.shown(image) : image;
}

bool ViewerSession::writeScreenshot(const core::Image& image, const std::string& path) {
    std::string error;
    if (!core::writePng(path, image, error)) {
        notify("screenshot failed: " + error);
        viewerSay(error);
        return false;
    }
    notify("screenshot: " + path);
    viewerSay("wrote " + path + " (" + std::to_string(image.width) + "x" +
            std::to_string(image.height) + ")");
    return true;
}

bool ViewerSession::writeHdrFrame() {
    std::string error;
    const core::Image image = mRenderer->readback();
    if (!core::writeHdr(mConfig.hdrPath, image, error)) {
        viewerSay(error);
        return false;
    }
    viewerSay("wrote " + mConfig.hdrPath + " (" + std::to_string(image.width) + "x" +
            std::to_string(image.height) + ", linear radiance)");
    return true;
}

void ViewerSession::drawOverlay(double seconds) {
    if (mUi.draw(uiFrame(seconds * 1000.0), mSettings, mProfiler)) {
        std::string error;
        if (!mRenderer->setSettings(mSettings, error)) {
            notify(error);
            viewerSay(error);
        }
    }
}

} // namespace gi::app
