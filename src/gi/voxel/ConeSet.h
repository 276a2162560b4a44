// The diffuse cones a surface point traces over its hemisphere (voxel.cones, cone_tracing.glsl):
// one along the normal and one or two rings around it. Each cone stands for the part of the
// cosine-weighted hemisphere around it, so E_ind = pi x sum of weight x cone radiance.
//
// - 9 cones, the thesis' (4.2.5) and the fixed plan's: eight at 50 degrees, 45-degree
//   apertures; the central cone takes the cap up to halfway to the ring (sin^2 25 degrees =
//   0.18), each ring cone an eighth of the rest.
// - 19 cones, the adaptive plan's (the default): 6 and 12 in two rings, every cone 1/19 of the
//   cosine-weighted hemisphere (bands of equal sin^2 theta), each ring at its band's middle,
//   apertures of 37.3 degrees (a cap of 1/19 of the hemisphere's solid angle): the cones tile
//   the hemisphere, where the thesis' leave about a third of its solid angle between them.
//   More directions, not the narrower aperture, make most of the difference on the
//   scoreboard (accuracy-analysis.md).
//
// With voxel.cone_interleave (off by default) the pixels of a checkerboard trace alternate
// halves of each ring, weighted twice, and the edge-aware filter merges them: 10 of the 19
// cones per pixel, about half the trace, for nearly the scoreboard of all 19. Not the default:
// trace reuse reprojects history bilinearly, which blends the halves, and a moving camera's
// result strays from the full trace's about 2.5 times as far as with every cone at every pixel.
#pragma once

#include "core/Settings.h"

#include <array>

namespace gi::voxel {

struct ConeRing {
    int count = 0;           // cones, evenly spaced in azimuth
    float elevation = 0.0f;  // angle from the normal, radians
    float weight = 0.0f;     // each cone's share of the cosine-weighted hemisphere
};

struct ConeSet {
    float centralWeight = 0.0f;   // the cone along the normal
    std::array<ConeRing, 2> rings{};
    float apertureDegrees = 0.0f; // every cone's full aperture

    // Cones one pixel traces when `classes` neighbouring pixels share the rings' cones.
    [[nodiscard]] int conesPerPixel(int classes) const;
    // The weights, which sum to 1 (the whole hemisphere).
    [[nodiscard]] float totalWeight() const;
};

// The set voxel.cones names once the plan has resolved it (VOXEL_CONES_THESIS or _RINGS;
// _PLAN, unresolved, counts as the adaptive plan's 19); apertureDegrees > 0 replaces the
// set's own.
[[nodiscard]] ConeSet coneSet(int cones, float apertureDegrees);

// Pixel classes sharing the rings' cones: 2 for 19 cones with voxel.cone_interleave and a
// filter to merge them (radius > 0 trace texels), else 1 (the thesis traces all 9 at every
// pixel).
[[nodiscard]] constexpr int conePixelClasses(int cones, bool interleave, int filterTexels) {
    return cones != VOXEL_CONES_THESIS && interleave && filterTexels > 0 ? 2 : 1;
}

} // namespace gi::voxel
