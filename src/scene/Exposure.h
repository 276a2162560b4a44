// Pre-exposure: every radiometric value on the GPU (light intensities, emission, and so every
// shadowed irradiance, voxel volume, atlas layer, indirect texture and the frame target) is
// multiplied by one scene-wide factor k, and the frame is divided by k when it is read back
// or presented. Half floats (RGBA16F volumes and atlas layers) hold 6e-5 .. 65504 with 11
// bits; a light of 1e7 cd overflows them and one of 1e-6 cd sinks into their denormals. k
// brings the scene's characteristic irradiance to about 1 whatever the units of the file.
//
// k is a power of two, so scaling and unscaling are exact in floating point: an image is the
// same, bit for bit wherever no half float rounds, for any k.
#pragma once

#include "scene/Scene.h"

#include <vector>

namespace gi::scene {

// The characteristic irradiance: the largest over the lights of colour x intensity / D^2
// for point and spot lights (D = the bounds' diagonal, the distance at which a light's
// irradiance is typical of the scene, not its 1/r^2 peak) and of colour x intensity for
// directional lights, and of pi x emission (the irradiance an emitter of that radiance gives
// to a surface facing it, up close). Zero for a dark scene.
[[nodiscard]] float characteristicIrradiance(const std::vector<Light>& lights,
        const Aabb& bounds, float maxEmission);

// The power of two nearest 1 / characteristicIrradiance, within 2^-64 .. 2^64 (the
// range in which k times any half float stays a finite float); 1 for a dark scene.
[[nodiscard]] float preExposure(const std::vector<Light>& lights, const Aabb& bounds,
        float maxEmission);

} // namespace gi::scene
