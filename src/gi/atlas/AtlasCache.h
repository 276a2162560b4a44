// Disk cache of built atlases, so a large scene (Sponza: 230k triangles) is segmented and
// packed once, not at every start. An entry is keyed by a 128-bit hash of everything the
// atlas depends on: the flattened world-space geometry (positions, indices, TEXCOORD_1 and
// whether every primitive has it), the AtlasOptions and kAtlasCacheFormat. Hashing the
// geometry as loaded rather than the file's bytes covers the .gltf and its buffers, scenes
// built in code and loader changes. One binary file per entry, <key>.atlas, written to a
// temporary name and renamed; it ends with a checksum of its contents. A file that is
// truncated, of another key or format, inconsistent with the mesh, or fails the checksum is
// ignored (and rebuilt and overwritten), never trusted.
#pragma once

#include "gi/atlas/AtlasBuilder.h"

#include <filesystem>
#include <string>

namespace gi::atlas {

// Bump whenever the builder's output for the same inputs changes.
constexpr std::uint32_t kAtlasCacheFormat = 2;

// 32 lowercase hex digits.
[[nodiscard]] std::string atlasCacheKey(const AtlasMesh& mesh, const AtlasOptions& options);

class AtlasCache {
public:
    explicit AtlasCache(std::filesystem::path directory);

    // $VOXATLAS_CACHE_DIR/atlas, else $XDG_CACHE_HOME/voxatlas/atlas, else
    // $HOME/.cache/voxatlas/atlas, else <system temp>/voxatlas-atlas.
    [[nodiscard]] static std::filesystem::path defaultDirectory();

    const std::filesystem::path& directory() const { return mDirectory; }
    [[nodiscard]] std::filesystem::path entryPath(const std::string& key) const;

    // True and `atlas` filled when a valid entry for `key` exists that fits `mesh`.
    [[nodiscard]] bool load(const std::string& key, const AtlasMesh& mesh, Atlas& atlas) const;
    // Creates the directory if needed; on failure nothing that looks valid is left behind.
    [[nodiscard]] bool store(const std::string& key, const Atlas& atlas, std::string& error) const;

private:
    std::filesystem::path mDirectory;
};

struct AtlasBuildInfo {
    bool cacheHit = false;
    double seconds = 0.0;           // wall time of the load or of the build (and store)
    std::string cacheFile;          // empty when caching is off
    std::string cacheError;         // a failed store (the atlas itself is fine)
    std::string texcoord1Rejection; // why the scene's TEXCOORD_1 was not used, if it has one
};

// Loads the atlas from `cache` (nullptr = no cache) or builds and stores it.
[[nodiscard]] bool loadOrBuildAtlas(const AtlasMesh& mesh, const AtlasOptions& options,
        const AtlasCache* cache, Atlas& atlas, AtlasBuildInfo& info, std::string& error);

} // namespace gi::atlas
