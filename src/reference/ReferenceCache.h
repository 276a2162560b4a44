// Disk cache of reference renders, so the bench and repeated `render --mode reference` runs pay
// for a ground-truth image once. An entry is keyed by a 128-bit hash of everything the image
// depends on: the scene as the renderer sees it (world transforms, vertex attributes, indices,
// materials, decoded texture pixels and sampler modes, lights — including ones added on the
// command line or by defaults), the camera's view and projection matrices, width, height,
// spp, bounces, seed and kReferenceCacheFormat; for glossy renders also the material model and
// every material's metallic and roughness factors (Lambertian keys leave them out, so entries
// made before the glossy model stay valid). Hashing the loaded scene rather than file bytes
// covers the .gltf/.glb and every buffer and image it references, scenes built in code, and
// loader changes, while byte edits that change nothing (whitespace) keep the entry.
// Files per entry, in the cache directory: <key>.{direct,indirect,final,coverage}.pfm (coverage
// replicated in RGB) and <key>.json (noise estimate, render time, ray counts, and a 128-bit
// checksum of every image). Every file is written to a temporary name and renamed, the JSON
// last. An entry that is incomplete, unreadable, of another key or size, or whose checksums do
// not match is ignored (and overwritten by the next store), never trusted.
#pragma once

#include "reference/ReferenceRenderer.h"

#include <filesystem>
#include <string>

namespace gi::reference {

// Bump whenever the renderer's output for the same inputs changes. 2: area lights and the sky
// sampled (next-event estimation), emission from the front side only, and emission found by
// the bounce from the camera hit counted as direct light.
constexpr int kReferenceCacheFormat = 2;

// 32 lowercase hex digits.
[[nodiscard]] std::string referenceCacheKey(const scene::Scene& scene,
        const scene::CameraView& camera, int width, int height,
        const ReferenceSettings& settings);

class ReferenceCache {
public:
    explicit ReferenceCache(std::filesystem::path directory);

    // $VOXATLAS_CACHE_DIR, else $XDG_CACHE_HOME/voxatlas/reference, else
    // $HOME/.cache/voxatlas/reference, else <system temp>/voxatlas-reference.
    [[nodiscard]] static std::filesystem::path defaultDirectory();

    const std::filesystem::path& directory() const { return mDirectory; }

    // True and `out` filled when a valid entry exists; otherwise `out` is left untouched.
    [[nodiscard]] bool load(const std::string& key, ReferenceResult& out) const;
    // Creates the directory if needed. On failure nothing that looks valid is left behind.
    [[nodiscard]] bool store(const std::string& key, const ReferenceResult& result,
            std::string& error) const;

private:
    std::filesystem::path mDirectory;
};

struct CachedRenderStatus {
    bool hit = false;         // loaded from the cache, nothing rendered
    std::string storeError;   // non-empty when the fresh render could not be cached
};

// Returns the cached image when there is a valid entry; otherwise renders (building the
// Embree scene only then), stores the result and returns it. A failed store is reported in
// `status` but does not fail the render. An empty result means the renderer failed (`error`).
[[nodiscard]] ReferenceResult renderReferenceCached(const scene::Scene& scene,
        const scene::CameraView& camera, int width, int height,
        const ReferenceSettings& settings, const ReferenceCache& cache,
        CachedRenderStatus& status, std::string& error, const ProgressCallback& progress = {});

} // namespace gi::reference
