// Reads glTF 2.0 accessors generically: every component type (float; byte, short and int,
// signed or unsigned, normalized or not), interleaved buffer views (byteStride) and sparse
// accessors, per glTF 2.0 sections 3.6.2 (accessors) and 3.11 (normalized integers):
// https://registry.khronos.org/glTF/specs/2.0/glTF-2.0.html#accessor-data-types
// Every byte range is checked in 64-bit arithmetic against its buffer view and buffer before
// anything is allocated or read, so hostile counts and offsets fail cleanly. Errors are
// "<element>: <what is wrong>", e.g. "accessors[3]: byteOffset + ... exceeds ...".
#pragma once

#include <tiny_gltf.h>

#include <cstdint>
#include <string>
#include <vector>

namespace gi::scene {

struct AccessorFloats {
    std::vector<float> values; // count * components, element-major
    int components = 0;        // 1 (SCALAR) .. 4 (VEC4)
    std::size_t count = 0;
};

// Number of components of a TINYGLTF_TYPE_* (SCALAR 1 .. MAT4 16), 0 when unknown.
int accessorComponentCount(int type);
// "SCALAR", "VEC3", ...; "unknown" otherwise.
const char* accessorTypeName(int type);

// Reads a SCALAR/VEC2/VEC3/VEC4 accessor as floats. Normalized integers map to [0, 1] (unsigned)
// or [-1, 1] (signed) as glTF specifies; other integers convert to their value. Accessors with
// more than maxCount elements are refused before allocation.
[[nodiscard]] bool readAccessorFloats(const tinygltf::Model& model, int accessor,
        std::uint64_t maxCount, AccessorFloats& out, std::string& error);

// Reads a SCALAR accessor of unsigned byte, short or int components (index data).
[[nodiscard]] bool readAccessorIndices(const tinygltf::Model& model, int accessor,
        std::uint64_t maxCount, std::vector<std::uint32_t>& out, std::string& error);

} // namespace gi::scene
