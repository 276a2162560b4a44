// The atlas layers every atlas pass reads or writes (formats and meaning in shared.h,
// BIND_TEX_ATLAS_*): the four G-buffer layers of the thesis (4.4), the gather's running sums
// and the lit atlas the resolve samples. All R x R, one level; the lit atlas is filtered
// bilinearly, the others are read texel by texel.
// A double-sided surface is two surfaces back to back, each lit, sending and receiving on its
// own side (as the path tracer shades them): its texels keep the side the normal points to in
// direct, sums and lit, and the other side in the three back layers. Scenes without
// double-sided materials get 1 x 1 back layers that no pass writes or reads.
// With gi.bounces = B > 1, bounce b = 1..B-1 gathers again from a layer of senders (the
// direct light plus rho/pi times the previous bounce's E_ind, redrawn before each further
// gather) into sums of its own, kept as the first gather's are; the lit atlas then holds the
// last bounce's E_ind, which counts every bounce before it.
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
    gl::Texture surfaceMask; // R8UI: which neighbours lie on the texel's surface (atlas.filter),
                             // drawn with the G-buffer
    gl::Texture directBack, sumsBack, litBack; // the same for the back of double-sided texels
    // gi.bounces > 1 only (else 1 x 1): what the further gathers' senders send,
    // RGBA16F: rgb = direct + rho/pi x the previous bounce's E_ind (W/(m^2 sr)), a = direct.a
    gl::Texture senders, sendersBack;
    // gi.bounces - 1 entries: the sums of bounce b at b - 1, as sums and sumsBack
    std::vector<gl::Texture> bounceSums, bounceSumsBack;

    // What bounce b (0 = the first gather) reads as sender radiance and sums into.
    const gl::Texture& senderRadiance(int bounce) const { return bounce == 0 ? direct : senders; }
    const gl::Texture& senderRadianceBack(int bounce) const {
        return bounce == 0 ? directBack : sendersBack;
    }
    const gl::Texture& sumsOf(int bounce) const {
        return bounce == 0 ? sums : bounceSums[std::size_t(bounce - 1)];
    }
    const gl::Texture& sumsBackOf(int bounce) const {
        return bounce == 0 ? sumsBack : bounceSumsBack[std::size_t(bounce - 1)];
    }
    [[nodiscard]] int bounceCount() const { return 1 + int(bounceSums.size()); }

    // A back layer to attach as a draw buffer: nullptr (output dropped) while it is 1 x 1.
    const gl::Texture* attachable(const gl::Texture& back) const {
        return backSides ? &back : nullptr;
    }

    void allocate(int resolution, bool backSides, int bounceCount = 1);
    // What allocate(resolution, backSides, bounceCount) would take, before taking it.
    [[nodiscard]] static std::vector<gl::MemoryItem> memoryFor(int resolution, bool backSides,
            int bounceCount = 1);
    // Whether a scene's atlas needs back layers: some material is double-sided.
    [[nodiscard]] static bool needsBackSides(const scene::Scene& scene);
};

} // namespace gi::atlas
