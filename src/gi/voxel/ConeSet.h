// The diffuse cones a surface point traces over its hemisphere (voxel.cones, cone_tracing.glsl):
// one along the normal and one or two rings around it. Each cone stands for the part of the
// cosine-weighted hemisphere around it, so E_ind = pi x sum of weight x cone radiance.
//
// - 9 cones, the thesis' (4.2.5) and the fixed plan's: eight at 50 degrees, 45-degree
//   apertures; the central cone takes the cap up to halfway to the ring (sin^2 25 degrees =
//   0.18), each ring cone an eighth of the rest.
// - 37 cones, the quality preset's: 6, 12 and 18 in three rings of equal shares, 26.6-degree
//   apertures. More accurate than 19 on every Cornell box but the open front's energy, at
//   twice the trace, so only the quality preset traces them (accuracy-analysis.md).
// - 19 cones, the adaptive plan's (the default): 6 and 12 in two rings, every cone 1/19 of the
//   cosine-weighted hemisphere (bands of equal sin^2 theta), each ring at its band's middle,
//   apertures of 37.3 degrees (a cap of 1/19 of the hemisphere's solid angle): the cones tile
//   the hemisphere, where the thesis' leave about a third of its solid angle between them.
//   More directions, not the narrower aperture, make most of the difference on the
//   scoreboard (accuracy-analysis.md).
//
// With voxel.jitter_elevation (off by default, on in the quality preset) the dither that turns
// the rings also moves each ring's cones within its band, so the filter averages over the
// band instead of reading it at one elevation: a small bright patch (a lamp's on the ceiling,
// a spot's pool) no longer falls between rings at the same elevation for a whole region.
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
    float bandLow = 0.0f;    // the part of the hemisphere the ring stands for: sin^2 theta from
    float bandHigh = 0.0f;   // bandLow to bandHigh
    // How far (in sin^2 theta) voxel.jitter_elevation moves the ring's cones up and down: as
    // far as both edges of the band, and no further than keeps a cone's rim above the surface.
    float riseReach = 0.0f;
};

struct ConeSet {
    float centralWeight = 0.0f;   // the cone along the normal
    std::array<ConeRing, 3> rings{};
    float apertureDegrees = 0.0f; // every cone's full aperture

    // Cones one pixel traces when `classes` neighbouring pixels share the rings' cones.
    [[nodiscard]] int conesPerPixel(int classes) const;
    // The weights, which sum to 1 (the whole hemisphere).
    [[nodiscard]] float totalWeight() const;
};

// The set voxel.cones names once the plan has resolved it (VOXEL_CONES_THESIS, _RINGS or
// _DENSE; _PLAN, unresolved, counts as the adaptive plan's 19); apertureDegrees > 0 replaces
// the set's own.
[[nodiscard]] ConeSet coneSet(int cones, float apertureDegrees);

// Pixel classes sharing the rings' cones: 2 for 19 or 37 cones with voxel.cone_interleave and a
// filter to merge them (radius > 0 trace texels), else 1 (the thesis traces all 9 at every
// pixel).
[[nodiscard]] constexpr int conePixelClasses(int cones, bool interleave, int filterTexels) {
    return cones != VOXEL_CONES_THESIS && interleave && filterTexels > 0 ? 2 : 1;
}

} // namespace gi::voxel
