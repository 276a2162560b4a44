// libFuzzer entry point for the glTF loader: feeds arbitrary bytes to loadGltfFromMemory (no
// file access) under ASan and UBSan, then checks the promises GltfLoader.h and Scene.h make:
// a failure is one line naming the input; a success has in-range indices, matching attribute
// counts, unit normals, finite values and RGBA8 textures, and survives addDefaults.
// Any broken promise aborts, so libFuzzer records the input as a crash.
#include "scene/GltfLoader.h"
#include "scene/SceneDefaults.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace {

using namespace gi::scene;

void require(bool condition, const char* promise) {
    if (!condition) {
        std::fprintf(stderr, "broken loader promise: %s\n", promise);
        std::abort();
    }
}

bool finite(const glm::vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

bool finite(const glm::mat4& m) {
    for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 4; ++r) {
            if (!std::isfinite(m[c][r])) return false;
        }
    }
    return true;
}

void checkScene(const Scene& scene) {
    for (const Primitive& p : scene.primitives) {
        const std::size_t n = p.positions.size();
        require(!p.indices.empty() && p.indices.size() % 3 == 0, "whole triangles");
        for (std::uint32_t index : p.indices) require(index < n, "indices in range");
        require(p.normals.size() == n, "one normal per vertex");
        for (const glm::vec3& normal : p.normals) {
            require(finite(normal) && std::abs(glm::length(normal) - 1.0f) < 1e-3f,
                    "unit normals");
        }
        for (const glm::vec3& position : p.positions) require(finite(position), "finite positions");
        require(p.texcoords0.empty() || p.texcoords0.size() == n, "TEXCOORD_0 count");
        require(p.texcoords1.empty() || p.texcoords1.size() == n, "TEXCOORD_1 count");
        require(p.colors.empty() || p.colors.size() == n, "COLOR_0 count");
        require(p.material >= -1 && p.material < int(scene.materials.size()), "material index");
        if (p.material >= 0) {
            const Material& m = scene.materials[std::size_t(p.material)];
            if (m.baseColorTexture >= 0) {
                require(!(m.baseColorTexCoord == 0 ? p.texcoords0 : p.texcoords1).empty(),
                        "texture coordinates for a textured material");
            }
        }
    }
    for (const Instance& instance : scene.instances) {
        require(instance.primitive >= 0 && instance.primitive < int(scene.primitives.size()),
                "instance primitive index");
        require(finite(instance.worldFromLocal), "finite instance transform");
    }
    for (const Material& m : scene.materials) {
        require(m.baseColorTexture >= -1 && m.baseColorTexture < int(scene.textures.size()),
                "base colour texture index");
        require(m.emissiveTexture >= -1 && m.emissiveTexture < int(scene.textures.size()),
                "emissive texture index");
    }
    for (const Texture& t : scene.textures) {
        require(t.width > 0 && t.height > 0 &&
                        t.rgba8.size() == std::size_t(t.width) * std::size_t(t.height) * 4,
                "RGBA8 textures");
    }
    for (const Light& light : scene.lights) {
        require(finite(light.position) && finite(light.direction) && finite(light.color) &&
                        std::isfinite(light.intensity),
                "finite lights");
    }
    for (const Camera& camera : scene.cameras) {
        require(finite(camera.worldFromCamera) && camera.yfov > 0.0f && camera.znear > 0.0f,
                "valid cameras");
    }
    if (!scene.instances.empty()) {
        require(!scene.bounds.empty() && finite(scene.bounds.min) && finite(scene.bounds.max),
                "finite bounds");
    }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    // Small limits keep each run fast and far below -rss_limit_mb.
    GltfLimits limits;
    limits.maxAccessorCount = 1u << 20;
    limits.maxVertices = 1u << 20;
    limits.maxIndices = 3u << 20;
    limits.maxInstances = 1u << 16;
    limits.maxImagePixels = 1u << 20;
    limits.maxTotalImagePixels = 1u << 22;

    Scene scene;
    std::string error;
    std::vector<std::string> warnings;
    if (!loadGltfFromMemory(data, size, "fuzz", "", scene, error, warnings, limits)) {
        require(error.rfind("fuzz: ", 0) == 0, "errors start with the input's name");
        require(error.find('\n') == std::string::npos, "errors are one line");
        return 0;
    }
    for (const std::string& warning : warnings) {
        require(warning.find('\n') == std::string::npos, "warnings are one line");
    }
    checkScene(scene);
    addDefaults(scene);
    require(!scene.lights.empty() && !scene.cameras.empty(), "defaults added");
    checkScene(scene);
    return 0;
}
