// Emissive surfaces as area lights (DESIGN.md: "a scene whose emissive surfaces light it gets
// no invented light: they are its lights").
//
// Every triangle whose material emits (emissiveFactor x the emissive texture's mean over the
// triangle, sampled at four points) becomes part of an area light. The triangles are grouped
// into clusters by median splits along the longest axis of their centres, largest cluster
// first, until each cluster has at most kMaxTrianglesPerLight triangles and spans at most a
// quarter of the scene's diagonal, or there are kMaxAreaLights clusters. Each cluster is one
// Light of type Area: its radiance is exact per triangle (passes integrate it analytically
// or sample it), while one shadow map from its area-weighted centre gives its visibility in
// the shadow-map method, which is why a cluster must stay small against the scene.
// At most kMaxEmitterTriangles triangles, the most powerful, become lights: every pass that
// shades with an area light visits its triangles, so their number bounds the cost per pixel.
#pragma once

#include "scene/Scene.h"

#include <cstddef>
#include <string>

namespace gi::scene {

inline constexpr std::size_t kMaxEmitterTriangles = 2048;
inline constexpr std::size_t kMaxTrianglesPerLight = 64;
inline constexpr std::size_t kMaxAreaLights = 32;

struct EmissionLightsReport {
    std::size_t emittingTriangles = 0;   // triangles with emission, before the cap
    std::size_t lightTriangles = 0;      // of them, the ones that became lights
    std::size_t lights = 0;              // area lights added
    double droppedPowerShare = 0.0;      // share of the emitted flux left out by the cap
    double emittingAreaShare = 0.0;      // emitting area / all surface area of the scene
    std::string summary;                 // one line for `info`; empty when nothing emits
};

// Appends the area lights to scene.lights (after the file's and the command line's lights).
EmissionLightsReport addEmissionLights(Scene& scene);

// Emitted flux of one triangle, W (luminance-weighted): pi x L x area x sides.
double emitterPower(const EmitterTriangle& triangle);

} // namespace gi::scene
