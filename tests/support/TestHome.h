// Tests never read or write the user's home. Every test program links this file, whose static
// initialiser points HOME, XDG_CACHE_HOME and VOXATLAS_CACHE_DIR into the build tree
// (VOXATLAS_TEST_HOME) before any test runs, however the program is started (ctest, or by
// hand); the programs a test runs inherit them, so the reference and atlas caches and Mesa's
// shader cache stay in the build tree too. Tests that need an empty cache make their own
// under the test output directory.
#pragma once

#include <string>

namespace gi::test {

// The directory that stands in for the user's home during tests.
[[nodiscard]] std::string testHome();

} // namespace gi::test
