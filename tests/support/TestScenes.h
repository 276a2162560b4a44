// Small scenes built in code for GPU tests, so expected values follow from their geometry.
#pragma once

#include "scene/Scene.h"

#include <string>

namespace gi::test {

// A horizontal square of half-size `halfSize` at height y, facing +Y, material 0.
[[nodiscard]] scene::Primitive horizontalSquare(float halfSize, float y);

// A horizontal square of half-size `halfSize` centred on (centre.x, y, centre.y), facing -Y
// (emitting downwards when its material emits), material `material`.
[[nodiscard]] scene::Primitive downwardSquare(float halfSize, float y, const glm::vec2& centre,
        int material);

// A grey floor (half-size 1, albedo 0.5, material 0) under a black square (material 1) of
// half-size `lampHalf` centred on (lampCentre.x, lampHeight, lampCentre.y), emitting `emission`
// downwards, seen from `eye` towards the floor's centre. No lights: scene::addEmissionLights
// makes the square's.
[[nodiscard]] scene::Scene floorUnderLamp(float lampHalf, float lampHeight,
        const glm::vec2& lampCentre, float emission, const glm::vec3& eye);

// Adds `primitive` with an identity transform and grows the scene bounds.
void addPrimitive(scene::Scene& scene, scene::Primitive primitive);

// A grey floor (half-size 1, albedo 0.5) with a black double-sided plate of half-size
// `plateHalf` at `plateHeight` above its centre, seen from (0, 0.3, 2.2): the shadow tests'
// occluder, whose shadow follows from similar triangles. No lights.
[[nodiscard]] scene::Scene floorWithPlate(float plateHalf, float plateHeight);

// A camera at `eye` looking at `target`.
[[nodiscard]] scene::Camera lookAtCamera(const glm::vec3& eye, const glm::vec3& target,
        float yfovDegrees);

// A glTF scene (absolute path, or relative to the source tree) with the scene defaults added;
// a load error fails the current test.
[[nodiscard]] scene::Scene loadTestScene(const std::string& path);

// The default light and camera where the scene has none, chosen from its geometry as the
// program chooses them (reference::addDefaultsFromGeometry).
void addDefaults(scene::Scene& scene);

// assets/cornell_box/cornell_box.gltf, as loadTestScene loads it.
[[nodiscard]] scene::Scene loadCornellBox();

} // namespace gi::test
