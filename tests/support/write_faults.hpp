#pragma once

// What the tests of every writer need to drive a write into a failure and look at what it left.
#include <cstddef>
#include <filesystem>
#include <functional>
#include <string>

namespace steerseg::test {

// The file's bytes as text ("" if unreadable).
std::string readText(const std::filesystem::path& path);
// Entries in a folder: a write that failed must leave no temporary beside its target.
std::size_t entryCount(const std::filesystem::path& dir);
// The files::WriteError's message `write` throws, or "" when it throws none.
std::string writeErrorOf(const std::function<void()>& write);
// The same, in a child process that may write files of at most `limitBytes`: the write loop
// fails with EFBIG partway, as on a full disk. The parent's folder is what the test checks.
std::string writeErrorUnderSizeLimit(const std::function<void()>& write, std::size_t limitBytes);

} // namespace steerseg::test
