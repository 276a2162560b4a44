#include "Process.h"

#include "ImageCompare.h"

#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>
#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

namespace gi::test {
namespace {

std::string slurp(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

} // namespace

std::string makeTempDir(const std::string& name) {
    const std::string dir = testOutputDir() + "/tmp/" + name + "-" + std::to_string(::getpid());
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

ProcessResult runProcess(const std::vector<std::string>& args, int timeoutSeconds,
        const std::vector<std::string>& extraEnv) {
    ProcessResult result;
    const std::string dir = makeTempDir("process");
    const std::string outPath = dir + "/stdout", errPath = dir + "/stderr";
    const pid_t pid = ::fork();
    if (pid == 0) {
        const int out = ::open(outPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        const int err = ::open(errPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        const int in = ::open("/dev/null", O_RDONLY);
        ::dup2(in, 0);
        ::dup2(out, 1);
        ::dup2(err, 2);
        for (const std::string& assignment : extraEnv) ::putenv(const_cast<char*>(assignment.c_str()));
        std::vector<char*> argv;
        for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
        argv.push_back(nullptr);
        ::execv(argv[0], argv.data());
        std::perror("execv");
        ::_exit(127);
    }
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(timeoutSeconds);
    int status = 0;
    for (;;) {
        const pid_t done = ::waitpid(pid, &status, WNOHANG);
        if (done == pid) break;
        if (std::chrono::steady_clock::now() > deadline) {
            ::kill(pid, SIGKILL);
            ::waitpid(pid, &status, 0);
            result.timedOut = true;
            break;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    if (!result.timedOut && WIFEXITED(status)) result.exitCode = WEXITSTATUS(status);
    result.out = slurp(outPath);
    result.err = slurp(errPath);
    std::filesystem::remove_all(dir);
    return result;
}

ProcessResult runVoxatlas(const std::vector<std::string>& args, int timeoutSeconds,
        const std::vector<std::string>& extraEnv) {
    std::vector<std::string> full{VOXATLAS_EXECUTABLE};
    full.insert(full.end(), args.begin(), args.end());
    return runProcess(full, timeoutSeconds, extraEnv);
}

} // namespace gi::test
