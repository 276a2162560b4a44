// The atlas layers every atlas pass reads or writes (formats and meaning in shared.h,
// BIND_TEX_ATLAS_*): the four G-buffer layers of the thesis (4.4), the gather's running sums
// and the lit atlas the resolve samples. All R x R, one level; the lit atlas is filtered
// bilinearly, the others are read texel by texel.
#pragma once

#include "gl/Objects.h"

#include <vector>

namespace gi::atlas {

struct AtlasTextures {
    int resolution = 0;
    gl::Texture direct;   // RGBA16F: rgb = outgoing direct radiance (W/(m^2 sr)), a = coverage
    gl::Texture normal;   // RGBA16F: xyz = unit normal, w = 1 if double-sided
    gl::Texture position; // RGBA32F: xyz = world position (m), w = sample area (m^2)
    gl::Texture albedo;   // RGBA16F: rgb = rho, a = coverage
    gl::Texture sums;     // RGBA32F: gather sums over all sample sets, a = receiver written
    gl::Texture lit;      // RGBA16F: rgb = E_ind (W/m^2) dilated into the gutters

    void allocate(int resolution);
    // What allocate(resolution) would take, before taking it.
    [[nodiscard]] static std::vector<gl::MemoryItem> memoryFor(int resolution);
};

} // namespace gi::atlas
