// Sponza is not part of the repository (README): tests read it from $VOXATLAS_SPONZA, else
// from ../shared/assets/sponza/Sponza.gltf beside the source tree. Where it is missing a test
// that needs it is skipped with a line saying how to provide it, and fails under CI ($CI set),
// which always has it.
#pragma once

#include <gtest/gtest.h>

#include <string>

namespace gi::test {

// The path Sponza is read from, whether or not the file is there.
[[nodiscard]] std::string sponzaPath();

// Why Sponza cannot be read from `path`, with how to provide it; empty when it can.
[[nodiscard]] std::string sponzaMissing(const std::string& path);

// True under CI, where a missing Sponza is a failure rather than a skip.
[[nodiscard]] bool sponzaRequired();

} // namespace gi::test

// Declares `const std::string var` holding Sponza's path, or ends the current test: skipped
// with the reason, or failed under CI.
#define VOXATLAS_SPONZA_OR_SKIP(var)                                                    \
    const std::string var = ::gi::test::sponzaPath();                                   \
    if (const std::string missing_ = ::gi::test::sponzaMissing(var); !missing_.empty()) { \
        if (::gi::test::sponzaRequired()) FAIL() << missing_;                           \
        GTEST_SKIP() << missing_;                                                       \
    }
