// The accuracy page's pictures: one strip per scene of indirect light, reference | voxel |
// atlas | vpl | |voxel - reference| | |atlas - reference| | |vpl - reference|. The four
// renders share one exposure (the
// reference's auto exposure) and the filmic curve, so brightness differences are real; the
// error maps run black - red - yellow - white, white at the reference's mean indirect
// luminance, so the same colour means the same error relative to the scene's light.
#pragma once

#include "bench/AccuracyReport.h"

#include <string>

namespace gi::bench {

// "accuracy_<scene>.png"
[[nodiscard]] std::string accuracyImageName(const std::string& scene);

[[nodiscard]] bool writeAccuracyImage(const std::string& path, const SuiteSceneResult& result,
        std::string& error);

} // namespace gi::bench
