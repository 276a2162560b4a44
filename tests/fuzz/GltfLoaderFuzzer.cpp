// libFuzzer entry point for the glTF loader and the atlas builder: feeds arbitrary bytes to
// loadGltfFromMemory (no file access) under ASan and UBSan, checks the promises GltfLoader.h
// and Scene.h make (SceneChecks.h), and builds the CPU atlas of every scene the loader accepts.
// Any broken promise aborts, so libFuzzer records the input as a crash.
#include "SceneChecks.h"

#include "scene/GltfLoader.h"

#include <cstdint>
#include <string>
#include <vector>

namespace {

// Scenes above this many triangles skip the atlas: a mutated sparse accessor can make a
// 64 KiB input hold a million vertices, and building their atlas would take seconds per run.
constexpr std::size_t kMaxAtlasTriangles = 1u << 16;
// Small, so each run stays fast, yet room for the charts of the seed scenes.
constexpr int kAtlasResolution = 128;

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    // Small limits keep each run fast and far below -rss_limit_mb.
    gi::scene::GltfLimits limits;
    limits.maxAccessorCount = 1u << 20;
    limits.maxVertices = 1u << 20;
    limits.maxIndices = 3u << 20;
    limits.maxInstances = 1u << 16;
    limits.maxImagePixels = 1u << 20;
    limits.maxTotalImagePixels = 1u << 22;

    gi::scene::Scene scene;
    std::string error;
    std::vector<std::string> warnings;
    if (!gi::scene::loadGltfFromMemory(data, size, "fuzz", "", scene, error, warnings, limits)) {
        gi::fuzz::checkLoadError(error, "fuzz");
        return 0;
    }
    gi::fuzz::checkLoadedScene(scene, warnings);
    if (scene.triangleCount() <= kMaxAtlasTriangles) {
        gi::fuzz::checkAtlas(scene, kAtlasResolution);
    }
    return 0;
}
