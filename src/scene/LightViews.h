// The views a light sees the scene through, for passes that render from every light: one
// orthographic view over the region for a directional light, one perspective view around a
// spot light's cone, six cube faces around a point light, and six cube faces around an area
// light's centre (drawn without the emitting surfaces; what weights each pixel's light says
// which faces matter). Voxel GI injects light through them (gi/voxel InjectPass), VPL GI draws
// its reflective shadow maps through them (gi/vpl ReflectiveShadowMapPass).
#pragma once

#include "scene/Scene.h"

#include <glm/glm.hpp>

#include <vector>

namespace gi::scene {

struct LightView {
    int light = 0;                       // index into the light table
    glm::mat4 viewProjection{1.0f};      // world -> clip
    glm::vec3 axis{0.0f, 0.0f, -1.0f};   // unit forward axis of the view
    bool orthographic = false;
    float footprint = 0.0f;              // one pixel: sr on the axis (perspective) or m^2 (ortho)
    bool areaLight = false;              // drawn without the area lights' own surfaces
};

// Views of every light but the sky (which has no position to see the scene from), `resolution`
// pixels per side each, covering `region`; none when the region is empty.
[[nodiscard]] std::vector<LightView> lightViews(const std::vector<Light>& lights,
        const Aabb& region, int resolution);

} // namespace gi::scene
