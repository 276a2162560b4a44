// Fills in what a scene needs to be drawn when its file does not provide it, so that any glTF
// opened looks right (DESIGN.md: "a scene without lights gets one documented default light"):
// the geometry is surveyed (scene/SceneSurvey.h: an enclosed interior, or an object / outdoor
// scene) and the kind decides
// - the light when the scene has no lights at all (scene/DefaultLights.h): a ceiling point
//   light in an interior, a sun over an object or outdoor scene;
// - the camera when it has no cameras (scene/DefaultCamera.h): standing inside an interior at
//   eye height, looking along its longest span; a three-quarter view framing an object.
// The survey is taken over defaultFramingBounds: scene.bounds, except that an empty scene (no
// triangles) or one with non-finite bounds uses the unit cube centred on the origin, and
// bounds smaller than 1 um (or 1e-6 of their distance from the origin) are padded to that size.
// Added entries have isDefault = true. Scenes that already have lights/cameras are unchanged.
#pragma once

#include "scene/RayCaster.h"
#include "scene/Scene.h"

#include <string>

namespace gi::scene {

// Why each default was chosen, for `voxatlas info`; empty where the file brought its own.
struct DefaultsReport {
    std::string lights;
    std::string camera;
};

DefaultsReport addDefaults(Scene& scene, const RayCaster& caster);

// The camera addDefaults adds to a scene without cameras; the viewer also offers it beside
// the file's own cameras.
[[nodiscard]] Camera defaultCamera(const Scene& scene, const RayCaster& caster);

// The bounds addDefaults surveys and frames: scene.bounds, or the substitute described above.
Aabb defaultFramingBounds(const Scene& scene);

} // namespace gi::scene
