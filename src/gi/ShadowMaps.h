// What a GI technique needs of the direct light's shadows: the maps of every light, already
// rendered for this frame, bound at their shared.h slots for shaders that shade direct light
// through shaders/common/shadows.glsl (the atlas G-buffer). The renderer's ShadowPass
// implements it; techniques see only this, so gi/ never reaches up into render/.
#pragma once

namespace gi {

class ShadowMaps {
public:
    virtual ~ShadowMaps() = default;
    // Binds the maps and the GpuShadow table at their shared.h slots.
    virtual void bind() const = 0;
};

} // namespace gi
