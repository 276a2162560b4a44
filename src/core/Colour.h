// The sRGB transfer function (IEC 61966-2-1): PNG files and glTF colour textures hold sRGB
// codes, everything the renderer computes is linear radiance (DESIGN.md).
#pragma once

namespace gi::core {

// 8-bit code / 255 to linear.
float srgbToLinear(float encoded);
// Linear to the encoded value in [0, 1]; clamps, and maps NaN to 0.
float linearToSrgb(float linear);

} // namespace gi::core
