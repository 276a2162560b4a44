// One run of `voxatlas view` in a window: the scene, the renderer, the overlay, the fly camera
// and the hotkeys, and the frame loop that ties them together. The frame-time budget
// (app/ResolutionController.h) sets the render resolution of each frame; files dropped on the
// window (or --drop FRAME:FILE) replace the scene through the same loading path as startup.
// ViewerSession.cpp has the loop, ViewerActions.cpp what keys and the overlay do,
// ViewerOpen.cpp the opening of dropped files.
#pragma once

#include "app/CommandLine.h"
#include "app/FlyCamera.h"
#include "app/FrameTimeLog.h"
#include "app/ResolutionController.h"
#include "app/Ui.h"
#include "app/ViewerCameras.h"
#include "app/ViewerExposure.h"
#include "gl/GpuProfiler.h"
#include "gl/ShaderLibrary.h"
#include "platform/GlfwWindow.h"
#include "render/FrameRenderer.h"
#include "render/PresentPass.h"

#include <chrono>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace gi::app {

// "voxatlas view: MESSAGE" on stderr.
void viewerSay(const std::string& message);

class ViewerSession {
public:
    ViewerSession(const Config& config, std::unique_ptr<scene::Scene> scene,
            std::unique_ptr<platform::GlfwWindow> window, const scene::CameraView& camera);
    int run();

private:
    struct Hotkey {
        std::string key;
        std::string help;
        std::function<void()> action;
    };

    // The key table H shows and handleKey() dispatches.
    void addHotkeys();
    // Builds the renderer, the presenter and the overlay; false with one message.
    bool start(std::string& error);
    // Window events, injected keys and dropped files of `frame`.
    void handleEvents(int frame);
    // Moves the camera and plays the animations by `seconds` of wall time.
    void advance(double seconds, int frame);
    // The camera of this frame: the fly camera and the scripted --move offset.
    [[nodiscard]] scene::CameraView currentView(float aspect) const;
    // Renders, meters and presents one frame; `fullResolution` overrides the budget.
    void renderFrame(glm::ivec2 windowSize, bool fullResolution, double seconds);
    // The overlay, and the settings its widgets changed.
    void drawOverlay(double seconds);
    void handleKey(const std::string& name);
    void selectMode(const render::ModeEntry& entry);
    void cycleOutput();
    void toggleBudget();
    // Applies a change to a copy of the settings; keeps it if the renderer accepts it.
    void changeSetting(const std::function<void(Settings&)>& change, const std::string& key);
    // Shows the camera mCameras selects (after C or Home).
    void showCamera();
    void reloadShaders();
    // Loads `path` as the new scene; on failure the old scene stays and the overlay says why.
    void openScene(const std::string& path);
    FlyInput readInput();
    UiFrame uiFrame(double frameMs) const;
    // The last frame as the window shows it (exposure and curve), for screenshots.
    core::Image shownFrame() const;
    bool writeScreenshot(const core::Image& image, const std::string& path);
    // --hdr: the last frame's linear radiance.
    bool writeHdrFrame();
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
    // Declared after mScene: the renderer refers to the scene and goes first.
    std::unique_ptr<render::FrameRenderer> mRenderer;
    render::PresentPass mPresent;
    Ui mUi;

    Settings mSettings;
    FlyCamera mCamera;
    scene::CameraView mStartView;             // the view the scene opened with
    ViewerCameras mCameras;
    ViewerExposure mExposure;
    ResolutionController mResolution;
    FrameTimeLog mFrameLog;
    float mBudgetWhenOff = 0.0f;              // the budget B restores
    glm::vec3 mScriptedOffset{0.0f};          // --move: metres moved so far
    std::optional<glm::mat4> mLastViewProjection;   // to tell a moving camera from a still one
    glm::ivec2 mInternalSize{0};              // render size of the last frame, before supersample
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
    std::string mOpenError;                   // the last dropped file that failed to open
};

} // namespace gi::app
