// Loads a glTF 2.0 scene (.gltf with external or base64-embedded buffers, or .glb) into a Scene
// and validates everything the passes rely on, so that they never re-check: triangles only
// (strips and fans become lists), indices in range, finite attributes and transforms, an
// acyclic single-parent node graph, valid material/texture/image/sampler references, and world
// coordinates within +-1e18 m (so squared distances and extents stay finite in float).
// Parsing is tinygltf's; accessors are read by GltfAccessorReader and images decoded by
// ImageDecoder (several threads). Supported extensions: KHR_lights_punctual and
// KHR_materials_emissive_strength; any other in extensionsRequired is an error.
// Every error is one line "<file>: <element>: <what is wrong>"; warnings have the same form.
// Nothing throws out of these functions, and `out` is only written on success.
#pragma once

#include "scene/Scene.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace gi::scene {

// Upper bounds that keep hostile files from exhausting memory; each is checked before the
// memory it guards is allocated. The defaults are far above any scene this project renders.
struct GltfLimits {
    std::uint64_t maxAccessorCount = 1ull << 28;    // elements in one accessor
    std::uint64_t maxVertices = 1ull << 28;         // decoded vertices over all primitives
    std::uint64_t maxIndices = 3ull << 28;          // decoded indices over all primitives
    std::uint64_t maxInstances = 1ull << 24;        // primitive placements over the node tree
    std::uint64_t maxImagePixels = 1ull << 28;      // per decoded image (16384 x 16384)
    std::uint64_t maxTotalImagePixels = 1ull << 30; // over all decoded images (4 GiB RGBA8)
    std::uint64_t maxJsonDepth = 128;               // nesting of JSON arrays and objects
};

// Loads `path`; .glb is recognised by its magic bytes, not by its extension. External buffers
// and images are resolved relative to the file's directory.
[[nodiscard]] bool loadGltf(const std::string& path, Scene& out, std::string& error,
        std::vector<std::string>& warnings, const GltfLimits& limits = {});

// Loads a .gltf or .glb held in memory. `displayName` starts every message. With an empty
// `baseDir` no file is ever opened (external buffers and images fail): the form fuzzing uses.
[[nodiscard]] bool loadGltfFromMemory(const std::uint8_t* data, std::size_t size,
        const std::string& displayName, const std::string& baseDir, Scene& out,
        std::string& error, std::vector<std::string>& warnings, const GltfLimits& limits = {});

} // namespace gi::scene
