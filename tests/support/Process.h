// Runs the voxatlas executable (or any program) with arguments, captures stdout, stderr and
// the exit status, and kills it after a time limit so a hang fails the test instead of CI.
#pragma once

#include <string>
#include <vector>

namespace gi::test {

struct ProcessResult {
    int exitCode = -1;       // -1 if it did not exit normally (signal, time-out)
    bool timedOut = false;
    std::string out, err;
};

[[nodiscard]] ProcessResult runProcess(const std::vector<std::string>& args,
        int timeoutSeconds = 120, const std::vector<std::string>& extraEnv = {});

// runProcess with the voxatlas executable prepended.
[[nodiscard]] ProcessResult runVoxatlas(const std::vector<std::string>& args,
        int timeoutSeconds = 120, const std::vector<std::string>& extraEnv = {});

// A fresh empty directory under the test output directory, removed by the caller if wanted.
[[nodiscard]] std::string makeTempDir(const std::string& name);

} // namespace gi::test
