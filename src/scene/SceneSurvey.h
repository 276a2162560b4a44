// Decides from the geometry alone whether a scene is an enclosed interior (a room, a hall, a
// roofless atrium) or an object / outdoor scene, so that a file without lights or cameras gets
// defaults that suit it (scene/SceneDefaults.h).
//
// The survey casts 128 rays, evenly spread over the sphere, from each of five points: the
// bounds' centre and the points a quarter of the bounds' width and depth away from it
// horizontally (so one pillar or statue at the centre does not decide alone). Each ray either
//  - hits a FRONT face (counter-clockwise as seen from the point): a surface facing the point,
//    as a room's walls, floor and ceiling face the inside of the room;
//  - hits a BACK face: the point is inside a closed object (a box seen from within);
//  - escapes: open sky, or the outside of an object.
// Rule: the scene is an INTERIOR when at least 60% of all survey rays hit front faces,
// otherwise an OBJECT (or outdoor) scene. The threshold separates the cases cleanly: a closed
// room sends 100% of its rays to front faces, a room with one open side (the Cornell box) about
// 5/6, Sponza's roofless atrium about 80%; an object on a ground plane at most about 50% (the
// downward half), a closed object 0% (all back faces), an open plane 0% (all escape).
// Winding decides front and back even for double-sided materials: their normals still point
// out of the object they close, as glTF exporters write them.
#pragma once

#include "scene/RayCaster.h"
#include "scene/Scene.h"

#include <optional>
#include <string>

namespace gi::scene {

enum class SceneKind { Interior, Object };

struct SceneSurvey {
    static constexpr int kRaysPerPoint = 128;
    static constexpr int kPoints = 5;
    static constexpr float kInteriorFrontFraction = 0.6f;

    SceneKind kind = SceneKind::Object;
    int rays = 0;
    int frontHits = 0;
    int backHits = 0;
    glm::vec3 centre{0.0f};             // the bounds' centre, the first survey point
    std::optional<float> floorBelow;    // distance straight down from the centre to a surface
    std::optional<float> ceilingAbove;  // distance straight up from the centre to a surface

    float frontFraction() const { return rays > 0 ? float(frontHits) / float(rays) : 0.0f; }
    float backFraction() const { return rays > 0 ? float(backHits) / float(rays) : 0.0f; }
    float escapeFraction() const { return rays > 0 ? 1.0f - frontFraction() - backFraction() : 1.0f; }
    // "interior (82% of survey rays hit front faces)", or for an object what the rays did.
    [[nodiscard]] std::string describe() const;
};

// Surveys the geometry inside `bounds` (the framing bounds of scene/SceneDefaults.h).
[[nodiscard]] SceneSurvey surveyScene(const Aabb& bounds, const RayCaster& caster);

// Rays that start on a surface skip it: hits closer than this fraction of the bounds' diagonal
// (at least 1 um) are ignored.
[[nodiscard]] float surveyMinDistance(const Aabb& bounds);

// `count` unit directions spread evenly over the sphere (a Fibonacci lattice).
[[nodiscard]] std::vector<glm::vec3> sphereDirections(int count);

} // namespace gi::scene
