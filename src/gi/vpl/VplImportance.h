// How much of each RSM texel's light the camera's view can receive, for drawing VPLs where they
// light what the camera sees (vpl.importance). The VPLs stay unbiased: a texel drawn with a
// weight of flux x importance sends flux x W / (count x weight) per copy, so each texel's
// expected flux is its own, and a share of every texel's weight does not depend on the view
// (kViewIndependentShare), so no texel is left out where the view's samples miss what it
// lights.
#pragma once

#include "gi/vpl/RsmTexel.h"

#include <glm/glm.hpp>

#include <vector>

namespace gi::vpl {

// A surface point the camera sees, and the normal of its side facing the eye.
struct ViewSample {
    glm::vec3 position{0.0f};
    glm::vec3 normal{0.0f};
};

// The share of the mean importance every lit texel keeps whatever the view sees.
inline constexpr float kViewIndependentShare = 0.1f;

// Per texel: the unoccluded transfer of its light to the view's samples, the gather's own
// kernel without visibility (cos at the texel x cos at the sample / max(B, r^2), summed over
// the samples), plus kViewIndependentShare x its flux-weighted mean. Without visibility it
// can only overestimate where the light goes, never miss it. All 1 when there are no samples.
[[nodiscard]] std::vector<float> viewImportance(const std::vector<RsmTexel>& texels,
        const std::vector<ViewSample>& samples, float clampArea);

} // namespace gi::vpl
