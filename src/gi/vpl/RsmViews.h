// The views a light's reflective shadow map is drawn from: one orthographic view over the scene
// for a directional light, one perspective view around a spot light's cone, six cube faces
// around a point light, and six cube faces around an area light's centre (its emitters' exact
// irradiance weights what they see, so the faces behind it hold nothing).
#pragma once

#include "scene/Scene.h"

#include <glm/glm.hpp>

#include <vector>

namespace gi::vpl {

struct RsmView {
    int light = 0;                       // index into the light table
    glm::mat4 viewProjection{1.0f};      // world -> clip
    glm::vec3 axis{0.0f, 0.0f, -1.0f};   // unit forward axis of the view
    bool orthographic = false;
    float footprint = 0.0f;              // one pixel: sr on the axis (perspective) or m^2 (ortho)
    bool areaLight = false;              // drawn without the area lights' own surfaces
};

// Views of every light but the sky (which has no position to see the scene from), `resolution`
// pixels per side each, covering `bounds`.
[[nodiscard]] std::vector<RsmView> rsmViews(const std::vector<scene::Light>& lights,
        const scene::Aabb& bounds, int resolution);

} // namespace gi::vpl
