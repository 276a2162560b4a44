// `--light` specs: punctual lights, a constant sky and a rectangular area light, each one
// `kind:field:field...` with comma-separated vectors (docs/usage.md).
#pragma once

#include "scene/Scene.h"

#include <string>

namespace gi::app {

// point:x,y,z:r,g,b:intensity, spot:x,y,z:dx,dy,dz:r,g,b:intensity[:inner_deg,outer_deg],
// dir:dx,dy,dz:r,g,b:intensity, sky:r,g,b:intensity (radiance colour x intensity from every
// direction), rect:cx,cy,cz:ux,uy,uz:vx,vy,vz:r,g,b:radiance (an area light of two triangles
// spanning centre +- u/2 +- v/2, emitting colour x radiance from the side cross(u, v) faces).
// False with a one-line error for anything else: unknown kinds, missing or extra fields,
// numbers that are not finite, negative colours or intensities, a zero direction, cone
// angles out of order, a rectangle of zero or non-finite area.
[[nodiscard]] bool parseLightSpec(const std::string& text, scene::Light& light, std::string& error);

} // namespace gi::app
