// Texture lookups of the reference renderer, matching what the raster passes sample: bilinear
// filtering, the glTF sampler's wrap modes, and sRGB colour decoded to linear before filtering
// (as an SRGB8_ALPHA8 texture on the GPU).
#pragma once

#include "scene/Scene.h"

#include <glm/glm.hpp>

namespace gi::reference {

// Bilinear lookup with the texture's wrap modes; alpha is linear. White for a texture without
// pixels.
glm::vec4 sampleTexture(const scene::Texture& texture, glm::vec2 uv);

} // namespace gi::reference
