// The viewer's exposure: auto (the frame's log-average luminance, core/ToneMap.h, adapted
// smoothly over time) or a manual EV, and the tone curve. Adaptation is exponential in EV
// with a time constant of kAdaptSeconds, so a step from a dark to a bright view settles in
// about a second; the first metered frame is taken as it is.
#pragma once

#include "core/ToneMap.h"
#include "render/ExposureMeter.h"
#include "render/FrameRenderer.h"

#include <optional>
#include <string>
#include <vector>

namespace gi::app {

class ViewerExposure {
public:
    static constexpr double kAdaptSeconds = 0.5;
    static constexpr float kEvStep = 0.5f;   // stops per key press

    explicit ViewerExposure(const core::ToneMapping& start);

    // Moves the auto exposure toward the one `logAverage` asks for, over `seconds`.
    void adapt(std::optional<float> logAverage, double seconds);
    // In auto mode, meters the renderer's last frame and adapts to it over `seconds`.
    void meter(const render::FrameRenderer& renderer, double seconds);
    // `radiance` as the window shows it: times exposure(), through curve().
    [[nodiscard]] core::Image shown(const core::Image& radiance) const;

    // The key actions; each returns the notice the overlay shows.
    std::string stepEv(float stops);
    std::string darker() { return stepEv(-kEvStep); }
    std::string brighter() { return stepEv(kEvStep); }
    std::string toggleAuto();
    std::string toggleCurve();

    struct Hotkey {
        const char* key;                        // platform::keyName() of the key
        const char* help;
        std::string (ViewerExposure::*action)();
    };
    static const std::vector<Hotkey>& hotkeys();

    bool automatic() const { return mMapping.autoExposure; }
    float ev() const { return mMapping.autoExposure ? mAdaptedEv : mMapping.ev; }
    float exposure() const;                      // 2^ev()
    core::ToneCurve curve() const { return mMapping.curve; }
    // "auto +1.25 EV, filmic"
    std::string label() const;

private:
    render::ExposureMeter mMeter;
    core::ToneMapping mMapping;
    float mAdaptedEv = 0.0f;
    bool mMetered = false;
};

} // namespace gi::app
