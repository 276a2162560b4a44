// The viewer's fly camera: a position and a yaw/pitch orientation (no roll, +Y up) moved by
// WASD/QE and turned by mouse drags, at a speed that follows the scene's size (0.25 x the
// bounds diagonal per second by default, x4 with Shift, scaled by the scroll wheel). Pure
// math on a small input struct, no window calls, so it is unit-tested without a display.
// Until the user moves or turns it, the camera keeps the exact view it started from (a glTF
// camera's roll and clip planes included), so the first frame matches `voxatlas render`.
#pragma once

#include "scene/CameraView.h"
#include "scene/Scene.h"

#include <glm/glm.hpp>

namespace gi::app {

// One frame of input, already decoded from the window.
struct FlyInput {
    bool forward = false, back = false;   // W, S
    bool left = false, right = false;     // A, D
    bool down = false, up = false;        // Q, E
    bool fast = false;                    // Shift: x kFastFactor
    bool look = false;                    // a mouse button that turns the camera is held
    glm::vec2 mouseDelta{0.0f};           // cursor motion since last frame, pixels, y down
    float scrollSteps = 0.0f;             // wheel steps since last frame, + = faster
};

class FlyCamera {
public:
    static constexpr float kSpeedPerDiagonal = 0.25f;   // default speed: diagonals per second
    static constexpr float kFastFactor = 4.0f;          // Shift multiplier
    static constexpr float kScrollFactor = 1.25f;       // speed x this per wheel step
    static constexpr float kMaxSpeedScale = 1000.0f;    // scroll range: default / .. x this
    static constexpr float kRadiansPerPixel = 0.0025f;  // mouse-look sensitivity
    static constexpr float kMaxPitch = 1.5533430f;      // 89 degrees: never straight up/down

    FlyCamera() = default;
    // Starts at `start` (its eye, look direction and vertical field of view).
    FlyCamera(const scene::CameraView& start, const scene::Aabb& sceneBounds);

    // Moves to another view, keeping the user's speed scale.
    void reset(const scene::CameraView& start);

    // Advances by `seconds` of input.
    void update(const FlyInput& input, float seconds);

    // The view for an output of the given aspect ratio (width / height).
    [[nodiscard]] scene::CameraView view(float aspect) const;

    const glm::vec3& position() const { return mPosition; }
    float yaw() const { return mYaw; }       // radians, 0 looks down -Z, + turns towards +X
    float pitch() const { return mPitch; }   // radians, + looks up
    float yfov() const { return mYfov; }
    // Current base speed in metres per second (without Shift).
    float speed() const { return mBaseSpeed * mSpeedScale; }
    [[nodiscard]] glm::vec3 forward() const;
    [[nodiscard]] glm::vec3 right() const;
    // True until the camera has moved or turned away from its start view.
    bool atStart() const { return mAtStart; }

private:
    glm::vec3 mPosition{0.0f};
    float mYaw = 0.0f, mPitch = 0.0f;
    float mYfov = 0.8f;
    float mBaseSpeed = 1.0f;
    float mSpeedScale = 1.0f;
    scene::Aabb mBounds;
    scene::CameraView mStart;
    bool mAtStart = true;
};

} // namespace gi::app
