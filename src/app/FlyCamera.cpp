#include "app/FlyCamera.h"

#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace gi::app {

FlyCamera::FlyCamera(const scene::CameraView& start, const scene::Aabb& sceneBounds)
    : mBounds(sceneBounds) {
    const float diagonal = glm::length(sceneBounds.size());
    mBaseSpeed = kSpeedPerDiagonal * (diagonal > 0.0f && std::isfinite(diagonal) ? diagonal : 1.0f);
    reset(start);
}

void FlyCamera::reset(const scene::CameraView& start) {
    mStart = start;
    mAtStart = true;
    mPosition = start.eye;
    mYfov = start.yfov;
    const glm::vec3 back = glm::vec3(glm::inverse(start.view)[2]);
    const glm::vec3 look = glm::length(back) > 0.0f ? -glm::normalize(back) : glm::vec3(0, 0, -1);
    mPitch = std::clamp(std::asin(std::clamp(look.y, -1.0f, 1.0f)), -kMaxPitch, kMaxPitch);
    // Looking straight up or down leaves the heading in the camera's up vector instead.
    const glm::vec3 up = glm::vec3(glm::inverse(start.view)[1]);
    const glm::vec2 heading = std::abs(look.y) < 0.9999f ? glm::vec2(look.x, -look.z)
                                                         : glm::vec2(-up.x, up.z) * look.y;
    mYaw = std::atan2(heading.x, heading.y);
}

glm::vec3 FlyCamera::forward() const {
    return {std::cos(mPitch) * std::sin(mYaw), std::sin(mPitch),
            -std::cos(mPitch) * std::cos(mYaw)};
}

glm::vec3 FlyCamera::right() const { return {std::cos(mYaw), 0.0f, std::sin(mYaw)}; }

void FlyCamera::update(const FlyInput& input, float seconds) {
    if (input.scrollSteps != 0.0f) {
        mSpeedScale = std::clamp(mSpeedScale * std::pow(kScrollFactor, input.scrollSteps),
                1.0f / kMaxSpeedScale, kMaxSpeedScale);
    }
    if (input.look && input.mouseDelta != glm::vec2(0.0f)) {
        mYaw = std::remainder(mYaw + input.mouseDelta.x * kRadiansPerPixel,
                2.0f * glm::pi<float>());
        mPitch = std::clamp(mPitch - input.mouseDelta.y * kRadiansPerPixel, -kMaxPitch, kMaxPitch);
        mAtStart = false;
    }
    auto axis = [](bool positive, bool negative) { return float(positive) - float(negative); };
    const glm::vec3 direction = forward() * axis(input.forward, input.back) +
                                right() * axis(input.right, input.left) +
                                glm::vec3(0.0f, 1.0f, 0.0f) * axis(input.up, input.down);
    if (glm::length(direction) > 0.0f && seconds > 0.0f) {
        const float metresPerSecond = speed() * (input.fast ? kFastFactor : 1.0f);
        mPosition += glm::normalize(direction) * metresPerSecond * seconds;
        mAtStart = false;
    }
}

scene::CameraView FlyCamera::view(float aspect) const {
    if (mAtStart) {
        scene::CameraView view = mStart;
        view.aspect = aspect;
        view.projection = glm::perspective(view.yfov, aspect, view.znear, view.zfar);
        return view;
    }
    return scene::cameraLookAt(mPosition, mPosition + forward(), mYfov, aspect, mBounds);
}

} // namespace gi::app
