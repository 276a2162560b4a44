// Points on the scene's triangles, spread by area: the receivers by which
// atlas.importance=surfaces weighs the senders' draw (AtlasSenderSamplingPass). They are
// chosen on the mesh (its triangles in scene order), not on the atlas, so two renderers of
// one scene pick the same points whatever the atlas' layout (a renderer built with an
// animated instance at another pose packs its charts elsewhere), and they move with the
// instances: the GPU takes their places from GpuScene's posed vertices.
#pragma once

#include "gi/atlas/AtlasMesh.h"

#include <cstdint>
#include <vector>

namespace gi::atlas {

struct SurfacePoint {                // std430, SURFACE_POINT_UINTS uints
    std::uint32_t vertex[3];         // the triangle's vertices (mesh = GpuScene indices)
    std::uint32_t doubleSided;       // 1: both sides receive
    float b1, b2;                    // barycentric weights of vertex[1] and vertex[2]
};

struct SurfacePoints {
    std::vector<SurfacePoint> points;
    double areaPerPoint = 0.0;       // m^2: the scene's surface area over the points' count
};

// `count` points stratified by area: point k falls at (k + 0.5) / count of the triangles'
// summed area (triangles in mesh order), where it lies within its triangle decides how far
// from the first vertex (the square root of the share, so the points are uniform over the
// triangle), a golden-ratio sequence in k the direction. Degenerate triangles get none; an
// empty mesh none at all.
[[nodiscard]] SurfacePoints surfacePoints(const AtlasMesh& mesh, int count);

} // namespace gi::atlas
