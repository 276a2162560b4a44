// Tests run with their own home and caches inside the build tree (support/TestHome.h), so a
// test run leaves the user's ~/.cache untouched.
#include "Process.h"
#include "TestHome.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

namespace gi::test {
namespace {

bool startsWith(const char* value, const std::string& prefix) {
    return value && std::string(value).rfind(prefix, 0) == 0;
}

TEST(TestHome, HomeAndEveryCacheLieInTheBuildTree) {
    const std::string home = testHome();
    EXPECT_TRUE(startsWith(std::getenv("HOME"), home)) << std::getenv("HOME");
    EXPECT_TRUE(startsWith(std::getenv("XDG_CACHE_HOME"), home));
    EXPECT_TRUE(startsWith(std::getenv("VOXATLAS_CACHE_DIR"), home));
    EXPECT_TRUE(startsWith(home.c_str(), VOXATLAS_TEST_OUTPUT_DIR "/"))
            << "the test home must lie in the build tree: " << home;
}

TEST(TestHome, ProgramsTheTestsRunInheritIt) {
    const ProcessResult r = runProcess({"/bin/sh", "-c", "printf %s \"$HOME\""}, 10);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.out, testHome());
}

} // namespace
} // namespace gi::test
