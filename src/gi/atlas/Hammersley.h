// Sample positions for the atlas gather (thesis 3.9 and 4.5, Wong et al. 1997, "Sampling with
// Hammersley and Halton points"): the 2D Hammersley set X_i = (i / N, Phi_2(i)), i = 0..N-1,
// with Phi_2 the base-2 radical inverse (the binary digits of i mirrored at the point). The
// points map the unit square onto the atlas. A Cranley-Patterson rotation (Cranley & Patterson
// 1976) shifts the whole set by one offset modulo 1, keeping its low discrepancy; successive
// offsets come from the R2 sequence (Roberts 2018), so rotated sets spread evenly over frames.
#pragma once

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace gi::atlas {

// Phi_2(i): 0.b1 b2 b3... for i = ...b3 b2 b1 in binary.
[[nodiscard]] double radicalInverse2(std::uint32_t i);

// The N points of the Hammersley set, x in [0, 1) increasing, y = Phi_2(i).
[[nodiscard]] std::vector<glm::vec2> hammersley(int count);

// Offset of rotated set k: (0, 0) for k = 0, then frac(k * (1/g, 1/g^2)), g the plastic
// number (the R2 sequence).
[[nodiscard]] glm::vec2 cranleyPattersonOffset(std::uint32_t k);

} // namespace gi::atlas
