#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>

namespace steerseg::files {

// A file that cannot be read or written. what() is one line naming the file and the problem.
// The base of scan::ScanError and WriteError, so code that treats every file failure alike
// catches this one type.
class FileError : public std::runtime_error {
  public:
    // Inline, so that a reader used alone (the GPU machine's benchmarks read NIfTI only) does
    // not pull in the dispatcher and with it every other reader's library.
    FileError(const std::filesystem::path& path, const std::string& problem)
        : std::runtime_error(path.string() + ": " + problem) {}
};

// An output that cannot be written (a mask, a file replaced atomically). The command line tells
// it from a scan that cannot be read (exit status 4, not 1).
class WriteError : public FileError {
  public:
    using FileError::FileError;
};

} // namespace steerseg::files
