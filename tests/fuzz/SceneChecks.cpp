#include "SceneChecks.h"

#include "gi/atlas/AtlasBuilder.h"
#include "gi/atlas/AtlasMesh.h"
#include "scene/SceneDefaults.h"

// The main build takes stb_rect_pack's implementation from the system libstb; here it is
// compiled with the sanitizers like the atlas builder that calls it.
#define STB_RECT_PACK_IMPLEMENTATION
#include <stb_rect_pack.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>

namespace gi::fuzz {
namespace {

using namespace gi::scene;

void require(bool condition, const char* promise) {
    if (!condition) {
        std::fprintf(stderr, "broken promise: %s\n", promise);
        std::abort();
    }
}

bool oneLine(const std::string& text) { return text.find('\n') == std::string::npos; }

bool finite(const glm::vec2& v) { return std::isfinite(v.x) && std::isfinite(v.y); }

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

void checkLoadError(const std::string& error, const std::string& name) {
    require(error.rfind(name + ": ", 0) == 0, "errors start with the input's name");
    require(oneLine(error), "errors are one line");
}

void checkLoadedScene(Scene& scene, const std::vector<std::string>& warnings) {
    for (const std::string& warning : warnings) require(oneLine(warning), "warnings are one line");
    checkScene(scene);
    addDefaults(scene, NothingHitCaster());
    require(!scene.lights.empty() && !scene.cameras.empty(), "defaults added");
    checkScene(scene);
}

std::size_t checkAtlas(const Scene& scene, int resolution) {
    const atlas::AtlasMesh mesh = atlas::flattenScene(scene);
    require(mesh.indices.size() == scene.triangleCount() * 3, "flattened triangle count");
    require(mesh.positions.size() == scene.vertexCount(), "flattened vertex count");
    atlas::AtlasOptions options;
    options.resolution = resolution;
    atlas::Atlas result;
    std::string error;
    if (!atlas::buildAtlas(mesh, options, result, error)) {
        require(!error.empty() && oneLine(error), "atlas refusals are one line");
        return 0;
    }
    require(result.indices.size() == mesh.indices.size(), "one atlas triangle per triangle");
    for (std::uint32_t index : result.indices) {
        require(index < result.vertices.size(), "atlas indices in range");
    }
    for (const atlas::AtlasVertex& v : result.vertices) {
        require(v.source < mesh.positions.size(), "atlas vertex source in range");
        require(v.chart < result.charts.size(), "atlas vertex chart in range");
        require(finite(v.uv) && v.uv.x >= 0.0f && v.uv.y >= 0.0f && v.uv.x <= 1.0f &&
                        v.uv.y <= 1.0f,
                "atlas coordinates inside the unit square");
    }
    for (const atlas::AtlasChart& chart : result.charts) {
        if (result.fromTexcoord1) break; // the file's own rectangles may touch the far edge
        require(chart.origin.x >= 0 && chart.origin.y >= 0 &&
                        chart.origin.x + chart.size.x <= resolution &&
                        chart.origin.y + chart.size.y <= resolution,
                "charts inside the atlas");
    }
    require(std::isfinite(result.texelSize) && result.texelSize >= 0.0, "finite texel size");
    return result.charts.size();
}

} // namespace gi::fuzz
