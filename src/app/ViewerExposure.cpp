#include "app/ViewerExposure.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace gi::app {

ViewerExposure::ViewerExposure(const core::ToneMapping& start) : mMapping(start) {
    mAdaptedEv = start.ev;
}

void ViewerExposure::adapt(std::optional<float> logAverage, double seconds) {
    if (!logAverage) return;
    const float target = std::log2(core::autoExposure(*logAverage));
    const float blend = mMetered ? float(1.0 - std::exp(-seconds / kAdaptSeconds)) : 1.0f;
    mAdaptedEv += (target - mAdaptedEv) * blend;
    mMetered = true;
}

void ViewerExposure::meter(const render::FrameRenderer& renderer, double seconds) {
    if (!mMapping.autoExposure) return;
    adapt(mMeter.measure({renderer.radiance(), renderer.renderSize(), renderer.radianceScale()}),
            seconds);
}

core::Image ViewerExposure::shown(const core::Image& radiance) const {
    if (exposure() == 1.0f && curve() == core::ToneCurve::None) return radiance;
    return core::applyToneMapping(radiance, exposure(), curve());
}

float ViewerExposure::exposure() const {
    return std::exp2(ev());
}

std::string ViewerExposure::stepEv(float stops) {
    // A step in auto mode starts manual exposure from where auto had got to.
    mMapping.ev = std::clamp(ev() + stops, -core::kMaxExposureEv, core::kMaxExposureEv);
    mMapping.autoExposure = false;
    return "exposure " + label();
}

std::string ViewerExposure::toggleAuto() {
    if (mMapping.autoExposure) {
        mMapping.ev = mAdaptedEv;
    } else {
        mAdaptedEv = mMapping.ev;
    }
    mMapping.autoExposure = !mMapping.autoExposure;
    return "exposure " + label();
}

std::string ViewerExposure::toggleCurve() {
    mMapping.curve = mMapping.curve == core::ToneCurve::Filmic ? core::ToneCurve::None
                                                               : core::ToneCurve::Filmic;
    return std::string("tone curve ") + core::toneCurveName(mMapping.curve);
}

const std::vector<ViewerExposure::Hotkey>& ViewerExposure::hotkeys() {
    static const std::vector<Hotkey> keys = {
            {"-", "exposure -1/2 EV (manual)", &ViewerExposure::darker},
            {"=", "exposure +1/2 EV (manual)", &ViewerExposure::brighter},
            {"X", "auto / manual exposure", &ViewerExposure::toggleAuto},
            {"T", "tone curve: filmic / none", &ViewerExposure::toggleCurve},
    };
    return keys;
}

std::string ViewerExposure::label() const {
    char text[64];
    std::snprintf(text, sizeof text, "%s %+.2f EV, %s", automatic() ? "auto" : "manual",
            double(ev()), core::toneCurveName(mMapping.curve));
    return text;
}

} // namespace gi::app
