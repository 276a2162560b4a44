// The atlas layers every atlas pass reads or writes (formats and meaning in shared.h,
// BIND_TEX_ATLAS_*): the four G-buffer layers of the thesis (4.4), the gather's running sums
// and the lit atlas the resolve samples. All R x R, one level; the lit atlas is filtered
// bilinearly, the others are read texel by texel.
// A double-sided surface is two surfaces back to back, each lit, sending and receiving on its
// own side (as the path tracer shades them): its texels keep the side the normal points to in
// direct, sums and lit, and the other side in the three back layers. Scenes without
// double-sided materials get 1 x 1 back layers that no pass writes or reads.
#pragma once

#include "gl/Objects.h"
#include "scene/Scene.h"

#include <vector>

namespace gi::atlas {

struct AtlasTextures {
    int resolution = 0;
    bool backSides = false; // the back layers are R x R
    gl::Texture direct;   // RGBA16F: rgb = outgoing direct radiance (W/(m^2 sr)), a = coverage
    gl::Texture normal;   // RGBA16F: xyz = unit normal, w = 1 if double-sided
    gl::Texture position; // RGBA32F: xyz = world position (m), w = sample area (m^2)
    gl::Texture albedo;   // RGBA16F: rgb = rho, a = coverage
    gl::Texture sums;     // RGBA32F: gather sums over all sample sets, a = receiver written
    gl::Texture lit;      // RGBA16F: rgb = E_ind (W/m^2) dilated into the gutters
    gl::Texture directBack, sumsBack, litBack; // the same for the back of double-sided texels

    // A back layer to attach as a draw buffer: nullptr (output dropped) while it is 1 x 1.
    const gl::Texture* attachable(const gl::Texture& back) const {
        return backSides ? &back : nullptr;
    }

    void allocate(int resolution, bool backSides);
    // What allocate(resolution, backSides) would take, before taking it.
    [[nodiscard]] static std::vector<gl::MemoryItem> memoryFor(int resolution, bool backSides);
    // Whether a scene's atlas needs back layers: some material is double-sided.
    [[nodiscard]] static bool needsBackSides(const scene::Scene& scene);
};

} // namespace gi::atlas
