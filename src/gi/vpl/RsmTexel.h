// One lit pixel of a reflective shadow map as the CPU reads it back: the surface the light
// sees there and the flux it reflects (VplSampler draws VPLs from these).
#pragma once

#include <glm/glm.hpp>

namespace gi::vpl {

struct RsmTexel {
    glm::vec3 position{0.0f};   // world space (m)
    glm::vec3 normal{0.0f};     // unit normal of the lit side
    glm::vec3 flux{0.0f};       // W (pre-exposed, as the GPU's lights)
    float area = 0.0f;          // m^2 of surface the pixel covers
    int light = 0;              // index into the light table
};

} // namespace gi::vpl
