// Owen-scrambled Sobol' points in 6 dimensions, for the reference renderer's pixel position
// (dimensions 0, 1), first bounce direction (2, 3) and first light's emission direction
// (4, 5). Every point is uniformly distributed (so estimates stay unbiased), and the first 2^m
// points of one scrambled sequence are stratified in every dimension and, for dimensions
// (0, 1), in every 2D elementary interval, which removes most of the noise of the pixel
// average and of the one-bounce integral (PBRT 3rd ed. 7.4 "(0,2)-sequence sampler").
// Scrambling is hash-based nested uniform scrambling with a shuffled index: B. Burley,
// "Practical Hash-based Owen Scrambling", JCGT 9(4), 2020. Direction numbers: S. Joe and
// F. Y. Kuo, new-joe-kuo-6.21201 (dimensions 2-6 of their table; dimension 1 is the van der
// Corput sequence).
#pragma once

#include <cstdint>

namespace gi::reference {

constexpr int kSobolDimensions = 6;

// Unscrambled Sobol' coordinate of point `index` in `dimension` (0..5), as a 32-bit fraction.
[[nodiscard]] std::uint32_t sobol(std::uint32_t index, int dimension);

// Owen-scrambled, index-shuffled coordinate in [0, 1); `seed` selects the scramble, so
// different seeds give independent randomisations of the same point set.
[[nodiscard]] float sobolOwen(std::uint32_t index, int dimension, std::uint32_t seed);

// The same points, all dimensions at once and faster: per-seed scramble keys are computed
// once, and the Sobol' matrices are applied a byte at a time from tables in bit-reversed
// order, which saves the bit reversals between the index shuffle and the scramble.
class OwenSobolSampler {
public:
    explicit OwenSobolSampler(std::uint32_t seed);
    // out[d] == sobolOwen(index, d, seed) for every dimension d.
    void point(std::uint32_t index, float out[kSobolDimensions]) const;

private:
    std::uint32_t mSeed;
    std::uint32_t mDimensionSeeds[kSobolDimensions];
};

} // namespace gi::reference
