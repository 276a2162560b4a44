// The accuracy page's pictures: one strip per scene of indirect light, reference | voxel |
// atlas | vpl | voxel - reference | atlas - reference | vpl - reference. The four renders
// share one exposure (the reference's auto exposure) and the filmic curve, so brightness
// differences are real. The error maps are signed, because a mean hides where light is gained
// and lost: black where a render matches, red where it is too bright, blue where it is too
// dark, at full strength where the difference reaches the reference's mean indirect
// luminance, so the same colour means the same error relative to the scene's light.
#pragma once

#include "bench/AccuracyReport.h"

#include <glm/vec3.hpp>

#include <string>

namespace gi::bench {

// "accuracy_<scene>.png"
[[nodiscard]] std::string accuracyImageName(const std::string& scene);

// The error map's colour for a luminance difference (render - reference) against `scale`
// (the reference's mean): red for light gained, blue for light lost, black for none.
[[nodiscard]] glm::vec3 signedErrorColour(float difference, float scale);

[[nodiscard]] bool writeAccuracyImage(const std::string& path, const SuiteSceneResult& result,
        std::string& error);

} // namespace gi::bench
