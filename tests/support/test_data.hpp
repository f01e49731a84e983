#pragma once

#include <filesystem>
#include <gtest/gtest.h>
#include <optional>

namespace steerseg::test {

// The real-scan folder (STEERSEG_DATA_DIR, default ../shared/data beside the checkout), or
// nullopt where it is absent.
std::optional<std::filesystem::path> dataDir();

// A file or folder under the data folder, or nullopt if it is not there.
std::optional<std::filesystem::path> dataPath(const std::filesystem::path& relative);

// The steerseg binary under test (for command-line tests).
std::filesystem::path steersegBinary();

// A fresh empty temporary folder for one test.
std::filesystem::path tempDir(const std::string& name);

} // namespace steerseg::test

// Skips the current test, saying which data is missing and where it was looked for.
#define STEERSEG_REQUIRE_DATA(var, relative)                                                       \
    const auto var##_opt = ::steerseg::test::dataPath(relative);                                   \
    if (!var##_opt) {                                                                              \
        GTEST_SKIP() << "real scan data '" << (relative)                                           \
                     << "' not found (set STEERSEG_DATA_DIR; default ../shared/data)";             \
    }                                                                                              \
    const std::filesystem::path var = *var##_opt
