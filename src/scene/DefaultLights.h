// The light a scene gets when its file has no punctual lights, chosen from the geometry survey
// (scene/SceneSurvey.h):
// - INTERIOR: one white point light under the ceiling: on the vertical through the bounds'
//   centre, 90% of the way from the floor found straight below the centre to the ceiling
//   found straight above it (the bounds' bottom / top where those rays escape, as in a
//   roofless atrium). Its intensity I = d^2, d its height above the centre, gives 1 W/m^2
//   at the centre on a surface facing it (E = I / d^2, DESIGN.md radiometry); d counts as at
//   least a quarter of the room's height, for a centre close under the ceiling. If rays from that point see more back faces than
//   front faces, the point is inside a closed object, and the scene gets the sun instead.
// - OBJECT or outdoor: a white sun (directional light) giving 1 W/m^2 on a surface facing it,
//   50 degrees above the horizon, from the side of the camera that will show the scene
//   (the file's first camera, else the default camera's azimuth) turned 30 degrees to its
//   left, so the faces the camera sees are lit, and lit unevenly enough to show their shape.
#pragma once

#include "scene/RayCaster.h"
#include "scene/Scene.h"
#include "scene/SceneSurvey.h"

#include <string>
#include <vector>

namespace gi::scene {

struct LightChoice {
    std::vector<Light> lights;
    std::string why;   // e.g. "interior (82% of survey rays hit front faces) -> ceiling point light"
};

// `framing`: the bounds the survey was taken over (defaultFramingBounds); `cameraEye`: where
// the camera that will show the scene stands.
[[nodiscard]] LightChoice chooseDefaultLights(const Aabb& framing, const SceneSurvey& survey,
        const RayCaster& caster, const glm::vec3& cameraEye);

} // namespace gi::scene
