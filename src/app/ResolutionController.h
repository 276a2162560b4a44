// The viewer's frame-time budget (view.frame_budget_ms): while the camera moves, frames are
// rendered at a reduced internal resolution picked so that they take about the budget; when
// the camera stops, frames return to the full resolution, so a still view converges to the
// full-quality image (the GI techniques keep their caches and accumulation meanwhile: the
// atlas lives in texture space and the voxel caches follow the cascades, not the pixels).
//
// The cost of a frame is modelled as proportional to its pixel count: a frame of t ms at
// scale s asks for the area s^2 * budget / t next. A fixed cost (shadow maps, voxelization,
// the atlas gather) only makes the steps fall short, so the scale approaches the budget from
// one side instead of overshooting. Hysteresis keeps it from oscillating: decisions use the
// median of the last frames at the current scale, nothing changes while that median is within
// kTolerance of the budget, and scales are powers of 2^(-1/kStepsPerOctave) (each step changes
// the pixel count by 19%, less than the dead band is wide). The scale found while
// moving is kept for the next time the camera moves; the first motion starts from the still
// frames' cost. Pure arithmetic on the times it is given, so it is unit-tested without a GPU.
#pragma once

#include <glm/glm.hpp>

#include <vector>

namespace gi::app {

class ResolutionController {
public:
    static constexpr float kMinScale = 0.125f;    // never below an eighth of the window per axis
    static constexpr int kStepsPerOctave = 8;     // scale steps per halving of the scale
    static constexpr double kTolerance = 0.15;    // dead band around the budget
    static constexpr int kMedianFrames = 3;       // frames the decisions look at
    static constexpr int kGraceFrames = 1;        // unchanged frames still treated as moving

    // `budgetMs` 0 = no budget: every frame at full resolution.
    explicit ResolutionController(double budgetMs = 0.0);

    void setBudget(double budgetMs);
    [[nodiscard]] double budgetMs() const { return mBudgetMs; }
    [[nodiscard]] bool enabled() const { return mBudgetMs > 0.0; }

    // Starts a frame: whether the camera changed since the last one, and whether this frame
    // must be full resolution anyway (a screenshot). Returns the scale (per axis, (0, 1]) to
    // render the frame at.
    float beginFrame(bool cameraChanged, bool fullResolution = false);
    // Ends it with the time it took, in ms.
    void endFrame(double frameMs);

    // The last frame's scale, and whether it was rendered as a moving one (reduced).
    [[nodiscard]] float scale() const { return mFrameScale; }
    [[nodiscard]] bool moving() const { return mFrameMoving; }

    // `full` scaled and rounded, at least one pixel per axis.
    [[nodiscard]] static glm::ivec2 scaledSize(glm::ivec2 full, float scale);

private:
    // The scale whose area makes `frameMs` at `scale` take the budget, clamped and quantised.
    [[nodiscard]] float scaleForBudget(float scale, double frameMs) const;
    void recordMoving(double frameMs);

    double mBudgetMs = 0.0;
    int mUnchangedFrames = kGraceFrames + 1;   // a session starts still
    float mMovingScale = 0.0f;                 // 0 = not known yet
    std::vector<double> mMovingMs;             // frames at mMovingScale, oldest first
    std::vector<double> mStillMs;              // full-resolution still frames, oldest first
    float mFrameScale = 1.0f;
    bool mFrameMoving = false;
};

} // namespace gi::app
