#pragma once

#include <filesystem>
#include <gtest/gtest.h>
#include <optional>
#include <string>

namespace steerseg::test {

// The real-scan folder (STEERSEG_DATA_DIR, default ../shared/data beside the checkout), or
// nullopt where it is absent.
std::optional<std::filesystem::path> dataDir();

// A file or folder under the data folder, or nullopt if it is not there.
std::optional<std::filesystem::path> dataPath(const std::filesystem::path& relative);

// True when STEERSEG_REQUIRE_DATA=1 (CI sets it): missing real data fails a test instead of
// skipping it, so a CI run without its scans cannot pass.
bool dataRequired();

// Why `relative` is missing, for the skip or failure message.
std::string missingDataMessage(const std::filesystem::path& relative);

// The steerseg binary under test (for command-line tests).
std::filesystem::path steersegBinary();

// A fresh empty temporary folder for one test, removed when the test's process ends
// (STEERSEG_KEEP_TEST_DIRS=1 keeps it).
std::filesystem::path tempDir(const std::string& name);

} // namespace steerseg::test

// Skips the current test (fails it under STEERSEG_REQUIRE_DATA=1), saying which data is
// missing and where it was looked for. Usable in a test body or a fixture's SetUp.
#define STEERSEG_SKIP_OR_FAIL_FOR_DATA(relative)                                                   \
    do {                                                                                           \
        if (::steerseg::test::dataRequired()) {                                                    \
            GTEST_FAIL() << ::steerseg::test::missingDataMessage(relative);                        \
        }                                                                                          \
        GTEST_SKIP() << ::steerseg::test::missingDataMessage(relative);                            \
    } while (false)

// Declares `var`, the path of real data under the data folder, or skips (fails) the test.
#define STEERSEG_REQUIRE_DATA(var, relative)                                                       \
    const auto var##_opt = ::steerseg::test::dataPath(relative);                                   \
    if (!var##_opt) {                                                                              \
        STEERSEG_SKIP_OR_FAIL_FOR_DATA(relative);                                                  \
    }                                                                                              \
    const std::filesystem::path var = *var##_opt
