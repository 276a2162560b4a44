#include "reference/OwenSobol.h"

#include <array>
#include <bit>

namespace gi::reference {
namespace {

using DirectionTable = std::array<std::array<std::uint32_t, 32>, kSobolDimensions>;

// Direction numbers V_k (k = 1..32, stored at k - 1) from primitive polynomials of degree s
// with coefficients a and initial m_1..m_s (Joe & Kuo; Bratley & Fox, ACM TOMS 14(1), 1988):
// V_k = m_k 2^(32-k) for k <= s, else
// V_k = V_(k-s) ^ (V_(k-s) >> s) ^ XOR_(j=1..s-1) a_j V_(k-j), a_j the bits of a from the top.
DirectionTable makeDirections() {
    struct Polynomial {
        int s;
        std::uint32_t a;
        std::uint32_t m[4];
    };
    constexpr Polynomial kPolynomials[kSobolDimensions - 1] = {
        {1, 0, {1, 0, 0, 0}},
        {2, 1, {1, 3, 0, 0}},
        {3, 1, {1, 3, 1, 0}},
        {3, 2, {1, 1, 1, 0}},
        {4, 1, {1, 1, 3, 3}},
    };
    DirectionTable table{};
    for (int k = 0; k < 32; ++k) table[0][std::size_t(k)] = 1u << (31 - k);
    for (int d = 1; d < kSobolDimensions; ++d) {
        const Polynomial& p = kPolynomials[d - 1];
        std::array<std::uint32_t, 32>& v = table[std::size_t(d)];
        for (int k = 0; k < 32; ++k) {
            if (k < p.s) {
                v[std::size_t(k)] = p.m[k] << (31 - k);
                continue;
            }
            std::uint32_t value = v[std::size_t(k - p.s)] ^ (v[std::size_t(k - p.s)] >> p.s);
            for (int j = 1; j < p.s; ++j) {
                if ((p.a >> (p.s - 1 - j)) & 1u) value ^= v[std::size_t(k - j)];
            }
            v[std::size_t(k)] = value;
        }
    }
    return table;
}

const DirectionTable& directions() {
    static const DirectionTable table = makeDirections();
    return table;
}

std::uint32_t reverseBits(std::uint32_t x) {
    x = ((x >> 1) & 0x55555555u) | ((x & 0x55555555u) << 1);
    x = ((x >> 2) & 0x33333333u) | ((x & 0x33333333u) << 2);
    x = ((x >> 4) & 0x0F0F0F0Fu) | ((x & 0x0F0F0F0Fu) << 4);
    x = ((x >> 8) & 0x00FF00FFu) | ((x & 0x00FF00FFu) << 8);
    return (x >> 16) | (x << 16);
}

// tables[b][byte][d] = reverse(XOR of V_d[k] over the bits k of the index set in `byte`, where
// the byte holds bits 8b..8b+7 of the bit-reversed index (index bit 31 - j <-> bit j)).
using TableRow = std::array<std::uint32_t, kSobolDimensions>;
using ReversedTables = std::array<std::array<TableRow, 256>, 4>;

ReversedTables makeReversedTables() {
    const DirectionTable& v = directions();
    ReversedTables tables{};
    for (int b = 0; b < 4; ++b) {
        for (int byte = 0; byte < 256; ++byte) {
            for (int d = 0; d < kSobolDimensions; ++d) {
                std::uint32_t x = 0;
                for (int bit = 0; bit < 8; ++bit) {
                    if ((byte >> bit) & 1) x ^= v[std::size_t(d)][std::size_t(31 - (8 * b + bit))];
                }
                tables[std::size_t(b)][std::size_t(byte)][std::size_t(d)] = reverseBits(x);
            }
        }
    }
    return tables;
}

const ReversedTables& reversedTables() {
    static const ReversedTables tables = makeReversedTables();
    return tables;
}

// Burley 2020, listing 3: an approximately uniform permutation of the bit-reversed value in
// which each bit depends only on lower bits (Laine-Karras), i.e. a nested uniform scramble.
std::uint32_t laineKarrasPermutation(std::uint32_t x, std::uint32_t seed) {
    x += seed;
    x ^= x * 0x6C50B47Cu;
    x ^= x * 0xB82F1E52u;
    x ^= x * 0xC7AFE638u;
    x ^= x * 0x8D22F6E6u;
    return x;
}

std::uint32_t nestedUniformScramble(std::uint32_t x, std::uint32_t seed) {
    return reverseBits(laineKarrasPermutation(reverseBits(x), seed));
}

std::uint32_t hashCombine(std::uint32_t seed, std::uint32_t v) {
    return seed ^ (v + (seed << 6) + (seed >> 2));
}

std::uint32_t hash32(std::uint32_t x) {
    x ^= x >> 16;
    x *= 0x7FEB352Du;
    x ^= x >> 15;
    x *= 0x846CA68Bu;
    x ^= x >> 16;
    return x;
}

} // namespace

std::uint32_t sobol(std::uint32_t index, int dimension) {
    const std::array<std::uint32_t, 32>& v = directions()[std::size_t(dimension)];
    std::uint32_t x = 0;
    for (int bit = 0; index != 0; ++bit, index >>= 1) {
        if (index & 1u) x ^= v[std::size_t(bit)];
    }
    return x;
}

OwenSobolSampler::OwenSobolSampler(std::uint32_t seed) : mSeed(seed) {
    for (int d = 0; d < kSobolDimensions; ++d) {
        mDimensionSeeds[d] = hash32(hashCombine(seed, std::uint32_t(d)));
    }
}

void OwenSobolSampler::point(std::uint32_t index, float out[kSobolDimensions]) const {
    const ReversedTables& tables = reversedTables();
    // reverse(shuffled index): the Laine-Karras step of nestedUniformScramble without the
    // final reversal, which the reversed tables absorb.
    const std::uint32_t reversedIndex = laineKarrasPermutation(reverseBits(index), mSeed);
    const TableRow& r0 = tables[0][reversedIndex & 0xFFu];
    const TableRow& r1 = tables[1][(reversedIndex >> 8) & 0xFFu];
    const TableRow& r2 = tables[2][(reversedIndex >> 16) & 0xFFu];
    const TableRow& r3 = tables[3][reversedIndex >> 24];
    for (int d = 0; d < kSobolDimensions; ++d) {
        // reverse(sobol(shuffled, d)), scrambled in the reversed domain, then reversed back.
        const std::uint32_t reversed = r0[d] ^ r1[d] ^ r2[d] ^ r3[d];
        const std::uint32_t x = reverseBits(laineKarrasPermutation(reversed, mDimensionSeeds[d]));
        out[d] = float(x >> 8) * (1.0f / 16777216.0f);
    }
}

float sobolOwen(std::uint32_t index, int dimension, std::uint32_t seed) {
    const std::uint32_t shuffled = nestedUniformScramble(index, seed);
    const std::uint32_t x = nestedUniformScramble(sobol(shuffled, dimension),
            hash32(hashCombine(seed, std::uint32_t(dimension))));
    return float(x >> 8) * (1.0f / 16777216.0f);
}

} // namespace gi::reference
