#include "TestHome.h"

#include <cstdlib>
#include <filesystem>

namespace gi::test {
namespace {

// Runs before main(): the environment must be in place before a test or gtest reads it.
const bool kHomeInBuildTree = [] {
    const std::string home = testHome();
    std::filesystem::create_directories(home + "/.cache");
    ::setenv("HOME", home.c_str(), 1);
    ::setenv("XDG_CACHE_HOME", (home + "/.cache").c_str(), 1);
    ::setenv("VOXATLAS_CACHE_DIR", (home + "/.cache/voxatlas").c_str(), 1);
    return true;
}();

} // namespace

std::string testHome() {
    return VOXATLAS_TEST_HOME;
}

} // namespace gi::test
