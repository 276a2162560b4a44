// PCG32 (XSH RR 64/32): a small, fast generator with independent streams, used by the reference
// renderer so that every pixel owns a random sequence seeded from (seed, pixel, half) and the
// image does not depend on thread scheduling. M. E. O'Neill, "PCG: A Family of Simple Fast
// Space-Efficient Statistically Good Algorithms for Random Number Generation" (2014),
// https://www.pcg-random.org; seeding as in pcg32_srandom_r of the reference C implementation.
#pragma once

#include <cstdint>

namespace gi::reference {

// SplitMix64 finaliser (Steele, Lea, Flood 2014): spreads nearby integers (pixel indices) over
// all 64 bits before they seed a generator.
constexpr std::uint64_t mix64(std::uint64_t x) {
    x += 0x9E3779B97F4A7C15ull;
    x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
    x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
    return x ^ (x >> 31);
}

class Pcg32 {
public:
    Pcg32(std::uint64_t initState, std::uint64_t stream) {
        mState = 0;
        mIncrement = (stream << 1u) | 1u;
        nextUint();
        mState += initState;
        nextUint();
    }

    std::uint32_t nextUint() {
        const std::uint64_t old = mState;
        mState = old * 6364136223846793005ull + mIncrement;
        const auto xorShifted = std::uint32_t(((old >> 18u) ^ old) >> 27u);
        const auto rotation = std::uint32_t(old >> 59u);
        return (xorShifted >> rotation) | (xorShifted << ((32u - rotation) & 31u));
    }

    // Uniform in [0, 1): the top 24 bits, so the result is exact in float and never 1.
    float nextFloat() { return float(nextUint() >> 8) * (1.0f / 16777216.0f); }

private:
    std::uint64_t mState = 0;
    std::uint64_t mIncrement = 1;
};

} // namespace gi::reference
