#include "Sponza.h"

#include <cstdlib>
#include <filesystem>

namespace gi::test {

std::string sponzaPath() {
    const char* env = std::getenv("VOXATLAS_SPONZA");
    if (env && *env) return env;
    return (std::filesystem::path(VOXATLAS_DATA_DIR) / "../shared/assets/sponza/Sponza.gltf")
            .lexically_normal()
            .string();
}

std::string sponzaMissing(const std::string& path) {
    if (std::filesystem::is_regular_file(path)) return "";
    return "Sponza not found at " + path + ": put the Khronos glTF sample model Sponza there "
           "(2.0/Sponza/glTF) or set VOXATLAS_SPONZA to its .gltf (see README)";
}

bool sponzaRequired() {
    const char* ci = std::getenv("CI");
    return ci && *ci;
}

} // namespace gi::test
