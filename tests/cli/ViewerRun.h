// The viewer under Xvfb for the cli tests: `voxatlas view ARGS` on a private X server
// (xvfb-run), killed with its server if it hangs. Without xvfb-run the window tests skip,
// unless VOXATLAS_REQUIRE_GPU=1 makes that a failure.
#pragma once

#include "Process.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <unistd.h>
#include <vector>

namespace gi::test {

inline const std::string kViewerCornell =
        std::string(VOXATLAS_DATA_DIR) + "/assets/cornell_box/cornell_box.gltf";

// Whole viewer runs on llvmpipe take about a second; the limit is for a hung X server.
constexpr int kViewerTimeoutSeconds = 120;

inline std::string findProgram(const std::string& name) {
    const char* path = std::getenv("PATH");
    std::string dirs = path ? path : "/usr/bin:/bin";
    std::size_t start = 0;
    while (start <= dirs.size()) {
        const std::size_t end = std::min(dirs.find(':', start), dirs.size());
        const std::filesystem::path candidate =
                std::filesystem::path(dirs.substr(start, end - start)) / name;
        if (::access(candidate.c_str(), X_OK) == 0) return candidate.string();
        start = end + 1;
    }
    return {};
}

class ViewerWindowTest : public ::testing::Test {
protected:
    void SetUp() override {
        mXvfbRun = findProgram("xvfb-run");
        mTimeout = findProgram("timeout");
        if (mXvfbRun.empty() || mTimeout.empty()) {
            const char* require = std::getenv("VOXATLAS_REQUIRE_GPU");
            if (require && std::string(require) == "1") {
                FAIL() << "xvfb-run and timeout are needed to test the viewer window";
            }
            GTEST_SKIP() << "xvfb-run not found (Debian package xvfb): viewer window not tested";
        }
    }

    // Runs `voxatlas view ARGS` in `dir` on a private Xvfb server. `timeout` puts the run in
    // its own process group and kills the whole group (Xvfb included) if it hangs. Each run
    // asks for its own server number, so parallel test runs do not race for the same one.
    ProcessResult runView(const std::string& dir, const std::vector<std::string>& args) {
        static int run = 0;
        const int server = 100 + int(::getpid() % 400) * 8 + (run++ % 8);
        std::vector<std::string> command{mTimeout, "--kill-after=5",
                std::to_string(kViewerTimeoutSeconds - 10), mXvfbRun, "-a", "-n",
                std::to_string(server), "-s", "-screen 0 1024x768x24", "/usr/bin/env", "-C", dir,
                VOXATLAS_EXECUTABLE, "view"};
        command.insert(command.end(), args.begin(), args.end());
        return runProcess(command, kViewerTimeoutSeconds);
    }

    std::string mXvfbRun, mTimeout;
};

} // namespace gi::test
