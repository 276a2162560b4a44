#include "app/ResolutionController.h"

#include "core/Median.h"

#include <algorithm>
#include <cmath>

namespace gi::app {
namespace {

void keepRecent(std::vector<double>& values, double ms) {
    values.push_back(ms);
    if (values.size() > std::size_t(ResolutionController::kMedianFrames)) {
        values.erase(values.begin());
    }
}

} // namespace

ResolutionController::ResolutionController(double budgetMs) { setBudget(budgetMs); }

void ResolutionController::setBudget(double budgetMs) {
    mBudgetMs = std::max(budgetMs, 0.0);
    // Times measured against the old budget still describe the scales they were taken at.
}

float ResolutionController::beginFrame(bool cameraChanged, bool fullResolution) {
    mUnchangedFrames = cameraChanged ? 0 : std::min(mUnchangedFrames + 1, kGraceFrames + 1);
    mFrameMoving = enabled() && !fullResolution && mUnchangedFrames <= kGraceFrames;
    if (!mFrameMoving) {
        mFrameScale = 1.0f;
        return mFrameScale;
    }
    if (mMovingScale <= 0.0f) {
        mMovingScale = mStillMs.empty() ? 1.0f : scaleForBudget(1.0f, core::median(mStillMs));
    }
    mFrameScale = mMovingScale;
    return mFrameScale;
}

void ResolutionController::endFrame(double frameMs) {
    if (!enabled() || !(frameMs > 0.0) || !std::isfinite(frameMs)) return;
    if (mFrameMoving) {
        recordMoving(frameMs);
    } else {
        keepRecent(mStillMs, frameMs);
    }
}

void ResolutionController::recordMoving(double frameMs) {
    keepRecent(mMovingMs, frameMs);
    // A single frame decides alone only when it is far off; otherwise a second one confirms.
    const bool farOff = frameMs > 2.0 * mBudgetMs || frameMs < 0.5 * mBudgetMs;
    if (mMovingMs.size() < 2 && !farOff) return;
    const double estimate = mMovingMs.size() < 2 ? frameMs : core::median(mMovingMs);
    const bool over = estimate > mBudgetMs * (1.0 + kTolerance);
    const bool under = estimate < mBudgetMs * (1.0 - kTolerance) && mMovingScale < 1.0f;
    if (!over && !under) return;
    const float next = scaleForBudget(mMovingScale, estimate);
    if (next == mMovingScale) return;
    mMovingScale = next;
    mMovingMs.clear();
}

float ResolutionController::scaleForBudget(float scale, double frameMs) const {
    const double ratio = std::clamp(mBudgetMs / frameMs, 1.0 / 16.0, 16.0);
    const double wanted = std::sqrt(double(scale) * double(scale) * ratio);
    const double steps = std::round(-std::log2(wanted) * kStepsPerOctave);
    return float(std::clamp(std::exp2(-steps / kStepsPerOctave), double(kMinScale), 1.0));
}

glm::ivec2 ResolutionController::scaledSize(glm::ivec2 full, float scale) {
    if (scale >= 1.0f) return full;
    return glm::max(glm::ivec2(glm::round(glm::vec2(full) * scale)), glm::ivec2(1));
}

} // namespace gi::app
