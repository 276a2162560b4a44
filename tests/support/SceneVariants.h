// Variants of the Cornell box and tiny synthetic scenes for the stress matrix (issue "extremes"),
// written as self-contained glTF files. Each variant says how its mean radiance should relate
// to the unmodified Cornell box, so the test can tell a plausible image from garbage.
#pragma once

#include <string>

namespace gi::test {

struct SceneVariant {
    std::string path;             // the written .gltf
    // The mean radiance of this scene's image, over that of the unmodified Cornell box from
    // its own camera in the same mode; 0 when the variant is not comparable (use `ceiling`).
    double radianceFactor = 1.0;
    // An upper bound on any mean radiance the scene can produce (W/(m^2 sr)); 0 = none.
    double ceiling = 0.0;
    // A lower bound on the mean radiance of a lit scene; 0 = none.
    double floor = 0.0;
};

// The Cornell box's light intensity in assets/cornell_box/cornell_box.gltf (candela).
[[nodiscard]] double cornellLightIntensity();

// The whole box (geometry, light, camera) scaled by `scale` about the origin, the light's
// intensity scaled by scale^2 so irradiance, and so the image, stays the same.
[[nodiscard]] SceneVariant scaledCornell(const std::string& dir, double scale);

// The whole box moved by `offset` metres along x (camera included): float precision far
// from the origin.
[[nodiscard]] SceneVariant translatedCornell(const std::string& dir, double offset);

// The light's intensity set to `candela`: the image scales linearly with it.
[[nodiscard]] SceneVariant cornellWithLightIntensity(const std::string& dir, double candela);

// The one light replaced by a grid of `count` point lights under the ceiling sharing its
// total intensity.
[[nodiscard]] SceneVariant cornellWithLightGrid(const std::string& dir, int count);

// The box plus a mesh of degenerate triangles: zero-area (collinear and repeated indices),
// duplicate vertices and a needle a nanometre wide. They carry no area, so the image stays.
[[nodiscard]] SceneVariant cornellWithDegenerateTriangles(const std::string& dir);

// One 1 m right triangle of albedo 0.8 on the ground, a point light of 1 cd 0.5 m above its
// right-angle corner and a camera looking down at it. Lambertian radiance is at most
// rho/pi * I / h^2, the ceiling.
[[nodiscard]] SceneVariant singleTriangle(const std::string& dir);

// A scene with no nodes and no meshes: the image is the black background.
[[nodiscard]] SceneVariant emptyScene(const std::string& dir);

} // namespace gi::test
