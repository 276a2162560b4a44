#include "app/BenchCommon.h"

#include <cctype>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>

namespace gi::app {

namespace fs = std::filesystem;

std::string sponzaPath() {
    const char* env = std::getenv("VOXATLAS_SPONZA");
    if (env && *env) return env;
    const fs::path shared = fs::path(dataDirectory()) / "../shared/assets/sponza/Sponza.gltf";
    return shared.lexically_normal().string();
}

SceneChoice secondScene(const Config& config) {
    if (config.sceneGiven) return {config.scenePath, true};
    return {sponzaPath(), false};
}

bool isSponza(const std::string& path) {
    std::string stem = fs::path(path).stem().string();
    for (char& c : stem) c = char(std::tolower(static_cast<unsigned char>(c)));
    return stem == "sponza";
}

std::string displayPath(const std::string& path) {
    std::error_code ec;
    const fs::path relative = fs::relative(path, dataDirectory(), ec);
    if (ec || relative.empty()) return path;
    int parents = 0;
    for (const fs::path& part : relative) parents += part == "..";
    return parents <= 1 ? relative.string() : path;
}

std::string loadAverage() {
    std::ifstream in("/proc/loadavg");
    std::string one, five, fifteen;
    if (!(in >> one >> five >> fifteen)) return "";
    return one + " " + five + " " + fifteen;
}

std::string localTime() {
    const std::time_t now = std::time(nullptr);
    char text[64];
    std::strftime(text, sizeof text, "%Y-%m-%d %H:%M", std::localtime(&now));
    return text;
}

} // namespace gi::app
