// The reference renderer's low-discrepancy samples: the first 2^m Owen-scrambled Sobol'
// points are stratified in every dimension and, for dimensions (0, 1), in every 2D
// elementary interval of area 2^-m (a (0, m, 2)-net); scrambling keeps that and makes every
// point uniform, so seeds give independent, unbiased randomisations.
#include "reference/OwenSobol.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <vector>

namespace gi::reference {
namespace {

TEST(OwenSobol, UnscrambledStartsWithKnownPoints) {
    // Dimension 0 is van der Corput (1/2, 1/4, 3/4, ...); dimension 1 (x + 1) starts 1/2, 3/4,
    // 1/4 — the textbook Sobol' sequence (Bratley & Fox 1988).
    EXPECT_EQ(sobol(0, 0), 0u);
    EXPECT_EQ(sobol(1, 0), 0x80000000u);
    EXPECT_EQ(sobol(2, 0), 0x40000000u);
    EXPECT_EQ(sobol(3, 0), 0xC0000000u);
    EXPECT_EQ(sobol(1, 1), 0x80000000u);
    EXPECT_EQ(sobol(2, 1), 0xC0000000u);
    EXPECT_EQ(sobol(3, 1), 0x40000000u);
}

TEST(OwenSobol, EveryDimensionIsStratified) {
    for (std::uint32_t seed : {0u, 1u, 12345u, 0xDEADBEEFu}) {
        for (int d = 0; d < kSobolDimensions; ++d) {
            for (int m = 0; m <= 10; ++m) {
                const std::uint32_t n = 1u << m;
                std::set<std::uint32_t> cells;
                for (std::uint32_t i = 0; i < n; ++i) {
                    cells.insert(std::uint32_t(sobolOwen(i, d, seed) * float(n)));
                }
                EXPECT_EQ(cells.size(), n) << "seed " << seed << " dimension " << d << " m " << m;
            }
        }
    }
}

TEST(OwenSobol, FirstTwoDimensionsFormA02Net) {
    constexpr int kM = 8;
    constexpr std::uint32_t kN = 1u << kM;
    for (std::uint32_t seed : {0u, 7u, 99991u}) {
        std::vector<float> xs, ys;
        for (std::uint32_t i = 0; i < kN; ++i) {
            xs.push_back(sobolOwen(i, 0, seed));
            ys.push_back(sobolOwen(i, 1, seed));
        }
        for (int bx = 0; bx <= kM; ++bx) {
            const std::uint32_t nx = 1u << bx, ny = 1u << (kM - bx);
            std::set<std::uint64_t> cells;
            for (std::uint32_t i = 0; i < kN; ++i) {
                cells.insert(std::uint64_t(xs[i] * float(nx)) * ny +
                             std::uint64_t(ys[i] * float(ny)));
            }
            EXPECT_EQ(cells.size(), kN) << "seed " << seed << " intervals " << nx << "x" << ny;
        }
    }
}

TEST(OwenSobol, ScramblesAreUniformAndIndependent) {
    // Mean of one point over 4096 seeds: uniform in [0, 1) gives 0.5 with standard error
    // 0.29 / 64 = 0.0045; 0.02 is over 4 sigma.
    for (int d = 0; d < kSobolDimensions; ++d) {
        for (std::uint32_t index : {0u, 1u, 5u}) {
            double sum = 0.0;
            for (std::uint32_t seed = 0; seed < 4096; ++seed) sum += sobolOwen(index, d, seed);
            EXPECT_NEAR(sum / 4096.0, 0.5, 0.02) << "dimension " << d << " index " << index;
        }
    }
    EXPECT_NE(sobolOwen(3, 2, 1), sobolOwen(3, 2, 2));
}

TEST(OwenSobol, SamplerMatchesSingleDimensions) {
    for (std::uint32_t seed : {3u, 77u, 0xFFFFFFFFu}) {
        const OwenSobolSampler sampler(seed);
        for (std::uint32_t index : {0u, 1u, 2u, 3u, 100u, 255u, 256u, 65537u, 0xFFFFFFFFu}) {
            float u[kSobolDimensions];
            sampler.point(index, u);
            for (int d = 0; d < kSobolDimensions; ++d) {
                EXPECT_EQ(u[d], sobolOwen(index, d, seed));
            }
        }
    }
}

} // namespace
} // namespace gi::reference
