// Wording and number checks shared by the glTF loader's parts. Elements are named as in the
// JSON ("meshes[2].primitives[0]"), so every message reads "<element>: <what is wrong>"; and a
// JSON number counts as finite only when it is finite as the float the Scene stores.
#pragma once

#include <glm/glm.hpp>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstddef>
#include <string>

namespace gi::scene::gltf {

inline std::string indexed(const char* array, long long index) {
    return std::string(array) + "[" + std::to_string(index) + "]";
}

inline std::string primitiveName(int mesh, int primitive) {
    return indexed("meshes", mesh) + "." + indexed("primitives", primitive);
}

inline std::string doesNotExist(
        const char* what, long long index, std::size_t count, const char* array) {
    return std::string(what) + " " + std::to_string(index) + " does not exist (the file has " +
           std::to_string(count) + " " + array + ")";
}

// JSON numbers are doubles; the Scene stores floats, so "finite" means finite as a float.
inline bool finite(double v) { return std::isfinite(v) && std::abs(v) <= double(FLT_MAX); }

template <class Vec> bool allFinite(const Vec& values) {
    return std::all_of(values.begin(), values.end(), [](double v) { return finite(v); });
}

inline bool finiteMatrix(const glm::dmat4& m) {
    for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 4; ++r) {
            if (!finite(m[c][r])) return false;
        }
    }
    return true;
}

} // namespace gi::scene::gltf
