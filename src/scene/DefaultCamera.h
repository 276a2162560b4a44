// The camera a scene gets when its file has none, chosen from the geometry survey
// (scene/SceneSurvey.h):
// - INTERIOR: a 60-degree camera standing in the room at eye height, 1.7 m above the floor
//   found straight below the bounds' centre (half the room's height in a room lower than
//   3.4 m), looking level along the longest horizontal free span through that point (of the
//   four directions x, z and the two diagonals; Sponza: down the atrium). It steps back along
//   that span from the centre towards the wall behind, stopping a margin before it (30% of
//   the way, at least 0.5 m, at most half), so it sees most of the room's length without
//   the dark corners next to the wall (in Sponza, 65% of a square view is lit from there by
//   the ceiling light alone, 55% from 10% before the wall).
// - OBJECT or outdoor: a 45-degree camera looking at the bounds' centre from a three-quarter
//   view (azimuth 45 degrees from +Z towards +X, raised 25 degrees), as close as keeps every
//   corner of the bounds 5% inside a square view (so a flat board fills the frame as a box
//   does), but never inside 1.1 x the bounding sphere's radius. A FLAT scene (its thinnest
//   bounds side under 15% of its longest: a board, a single triangle, a ground with low
//   things on it) is seen more squarely, from 20 degrees off its plane's normal (leaning
//   the way the three-quarter view does), on the side most of its triangles face (rays
//   towards the plane from a 3x3 grid above it): at 45 degrees a board shows a sliver.
#pragma once

#include "scene/RayCaster.h"
#include "scene/Scene.h"
#include "scene/SceneSurvey.h"

#include <glm/gtc/constants.hpp>

#include <string>

namespace gi::scene {

// Where the object camera stands, also the side the default sun shines from.
constexpr float kObjectCameraAzimuth = glm::radians(45.0f);   // from +Z towards +X
constexpr float kObjectCameraElevation = glm::radians(25.0f);

struct CameraChoice {
    Camera camera;
    std::string why;   // e.g. "interior -> eye height 1.7 m, looking along z (36 m free)"
};

// `framing`: the bounds the survey was taken over (defaultFramingBounds).
[[nodiscard]] CameraChoice chooseDefaultCamera(const Aabb& framing, const SceneSurvey& survey,
        const RayCaster& caster);

} // namespace gi::scene
