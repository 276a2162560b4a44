// How punctual lights (point, spot, directional) reach a point, and how their emission is
// sampled for light subpaths; see DESIGN.md "Radiometric conventions" for the units.
#pragma once

#include "scene/Scene.h"

#include <glm/glm.hpp>

namespace gi::reference {

// Point, spot and directional lights: the ones lightGeometry() describes. Area lights are
// sampled by AreaLightSampler, the sky by cosine-distributed rays (PathTracer.h).
inline bool isPunctual(scene::LightType type) {
    return type == scene::LightType::Point || type == scene::LightType::Spot ||
           type == scene::LightType::Directional;
}

// False for lights that emit nothing or whose numbers are not finite (never NaN pixels);
// `radiant` is colour x intensity. An area light is usable when one of its triangles is.
bool usableLight(const scene::Light& light, const glm::vec3& radiant);

// Direction density (per steradian) with which lightSubpathDirection samples a light's
// emission: uniform over the sphere (point) or over the outer cone (spot). 0 for lights whose
// emission cannot be sampled (directional, or a spot with a zero-width cone): those are
// reached by next-event estimation alone.
float emissionPdf(const scene::Light& light);

// A direction of the light's emission, sampled with density emissionPdf(light) from (u1, u2).
glm::vec3 lightSubpathDirection(const scene::Light& light, float u1, float u2);

// How a punctual light reaches point p: wi (unit, towards the light), the shadow-ray length,
// and E / (colour x intensity x cos(theta)) per DESIGN.md: 1/d^2 (point), s^2/d^2 (spot),
// 1 (directional). False when the light cannot reach p (on it, or outside a spot's cone).
bool lightGeometry(const scene::Light& light, const glm::vec3& p, glm::vec3& wi,
        float& distance, float& factor);

} // namespace gi::reference
