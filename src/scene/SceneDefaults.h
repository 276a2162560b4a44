// Fills in what a scene needs to be drawn when its file does not provide it (DESIGN.md: "a
// scene without lights gets one documented default light"):
// - no lights: ONE white point light on the vertical axis through the bounds' centre, 90% of
//   the way up the bounds (inside the top, so it also lights closed rooms), or, for a flat
//   scene (height under 5% of its largest extent), a quarter of that extent above the centre.
//   Its intensity I = d^2 (d: distance to the bounds' centre) gives an irradiance of 1 W/m^2 at
//   the centre on a surface facing the light (E = I / d^2, DESIGN.md radiometry).
// - no cameras: a 45-degree perspective camera looking at the bounds' centre from the +Z side,
//   raised 15 degrees, at the distance where the bounding sphere fills the vertical view.
// An empty scene (no triangles), or one with non-finite bounds, uses the unit cube centred on
// the origin as its bounds; bounds smaller than 1 um (or 1e-6 of their distance from the
// origin) are padded to that size.
// Added entries have isDefault = true. Scenes that already have lights/cameras are unchanged.
#pragma once

#include "scene/Scene.h"

namespace gi::scene {

void addDefaults(Scene& scene);

// The bounds addDefaults frames: scene.bounds, or the substitute described above.
Aabb defaultFramingBounds(const Scene& scene);

} // namespace gi::scene
