// The promises GltfLoader.h, Scene.h and AtlasBuilder.h make about their results, checked on
// whatever the sanitizer builds feed them (the libFuzzer target and the scene_sanitizer run
// over the committed corpora). A broken promise prints which one and aborts, so libFuzzer
// records the input as a crash and ctest sees the run fail.
#pragma once

#include "scene/Scene.h"

#include <string>
#include <vector>

namespace gi::fuzz {

// A refused load: the message is one line that starts with "<name>: ".
void checkLoadError(const std::string& error, const std::string& name);
// An accepted load: in-range indices, matching attribute counts, unit normals, finite values,
// RGBA8 textures, one-line warnings; then the same after addDefaults.
void checkLoadedScene(scene::Scene& scene, const std::vector<std::string>& warnings);
// Flattens the scene and builds its atlas (CPU only, no GL) at `resolution`^2 texels: either
// a one-line refusal or an atlas whose every triangle has in-range vertices and finite texel
// coordinates inside the unit square, with every chart inside the atlas. Returns the chart
// count (0 when refused).
std::size_t checkAtlas(const scene::Scene& scene, int resolution);

} // namespace gi::fuzz
