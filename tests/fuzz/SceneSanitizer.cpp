// Runs the glTF loader (with file access, default limits) and the CPU atlas builder over
// scene files and directories of them, built with ASan and UBSan, checking the same promises
// as the fuzzer (SceneChecks.h). ctest runs it over the hostile-file corpus, the fuzzer's
// seeds, the Cornell box and, when present, Sponza. One line per file on stdout; any
// sanitizer report or broken promise aborts the run.
#include "SceneChecks.h"

#include "scene/GltfLoader.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

// The project's default atlas.resolution, so Sponza's charts are packed, not refused.
constexpr int kAtlasResolution = 1024;

// The arguments with each directory replaced by the .gltf and .glb files in it, sorted.
std::vector<std::string> sceneFiles(int argc, char** argv) {
    std::vector<std::string> files;
    for (int i = 1; i < argc; ++i) {
        if (!fs::is_directory(argv[i])) {
            files.emplace_back(argv[i]);
            continue;
        }
        std::vector<std::string> inDirectory;
        for (const fs::directory_entry& entry : fs::directory_iterator(argv[i])) {
            const std::string ext = entry.path().extension().string();
            if (ext == ".gltf" || ext == ".glb") inDirectory.push_back(entry.path().string());
        }
        std::sort(inDirectory.begin(), inDirectory.end());
        files.insert(files.end(), inDirectory.begin(), inDirectory.end());
    }
    return files;
}

} // namespace

int main(int argc, char** argv) {
    const std::vector<std::string> files = sceneFiles(argc, argv);
    if (files.empty()) {
        std::fprintf(stderr, "usage: scene_sanitizer SCENE_OR_DIRECTORY...\n");
        return 2;
    }
    std::size_t accepted = 0;
    for (const std::string& path : files) {
        const auto start = std::chrono::steady_clock::now();
        gi::scene::Scene scene;
        std::string error;
        std::vector<std::string> warnings;
        if (!gi::scene::loadGltf(path, scene, error, warnings)) {
            gi::fuzz::checkLoadError(error, path);
            std::printf("refused  %s\n", error.c_str());
            continue;
        }
        ++accepted;
        gi::fuzz::checkLoadedScene(scene, warnings);
        const std::size_t charts = gi::fuzz::checkAtlas(scene, kAtlasResolution);
        const double seconds =
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        std::printf("accepted %s: %zu triangles, %zu atlas charts at %d^2, %.2f s\n",
                path.c_str(), scene.triangleCount(), charts, kAtlasResolution, seconds);
    }
    std::printf("%zu files, %zu accepted, no sanitizer report\n", files.size(), accepted);
    return 0;
}
