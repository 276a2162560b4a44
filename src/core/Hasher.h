// A 128-bit content hash for cache keys and file checksums (the reference and atlas disk
// caches): two 64-bit lanes over 64-bit words, lane A FNV-1a's xor-multiply with an extra
// xorshift (so high input bits reach low state bits), lane B an add-multiply-rotate, each
// finished with MurmurHash3's fmix64. Not cryptographic; 128 bits make an accidental collision
// between cache entries negligible.
#pragma once

#include <bit>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <type_traits>
#include <vector>

namespace gi::core {

class Hasher {
public:
    void bytes(const void* data, std::size_t size) {
        const auto* p = static_cast<const unsigned char*>(data);
        std::size_t i = 0;
        for (; i + 8 <= size; i += 8) {
            std::uint64_t word;
            std::memcpy(&word, p + i, 8);
            mix(word);
        }
        std::uint64_t tail = 0;
        if (size > i) std::memcpy(&tail, p + i, size - i);
        mix(tail ^ (std::uint64_t(size - i) << 56));
        mLength += size;
    }
    template <class T> void value(const T& v) {
        static_assert(std::is_trivially_copyable_v<T>);
        bytes(&v, sizeof v);
    }
    template <class T> void vector(const std::vector<T>& values) {
        value(std::uint64_t(values.size()));
        bytes(values.data(), values.size() * sizeof(T));
    }
    void string(const std::string& text) {
        value(std::uint64_t(text.size()));
        bytes(text.data(), text.size());
    }

    std::uint64_t low() const { return finish(mA ^ mLength); }
    std::uint64_t high() const { return finish(mB + mLength); }
    std::string hex() const {
        char text[33];
        std::snprintf(text, sizeof text, "%016llx%016llx", static_cast<unsigned long long>(low()),
                static_cast<unsigned long long>(high()));
        return text;
    }

private:
    static std::uint64_t finish(std::uint64_t x) {
        x ^= x >> 33;
        x *= 0xff51afd7ed558ccdull;
        x ^= x >> 33;
        x *= 0xc4ceb9fe1a85ec53ull;
        return x ^ (x >> 33);
    }
    void mix(std::uint64_t word) {
        mA = (mA ^ word) * 0x100000001B3ull;
        mA ^= mA >> 29;
        mB = std::rotl((mB + word) * 0x9E3779B97F4A7C15ull, 27);
    }

    std::uint64_t mA = 0xCBF29CE484222325ull;   // FNV-1a 64 offset basis
    std::uint64_t mB = 0x84222325CBF29CE4ull;
    std::uint64_t mLength = 0;
};

} // namespace gi::core
