#include "files/file_append.hpp"

#include "files/file_error.hpp"
#include "files/file_write.hpp"
#include "files/io_faults.hpp"

#include <cerrno>
#include <fcntl.h>
#include <system_error>
#include <unistd.h>

namespace steerseg::files {

AppendFile::AppendFile(std::filesystem::path path) : path_(std::move(path)) {
    if (path_.has_parent_path()) {
        std::error_code ec; // open names the failure
        std::filesystem::create_directories(path_.parent_path(), ec);
    }
    fd_ = unlessInjected(IoCall::Open, [&] {
        return ::open(path_.c_str(), O_WRONLY | O_APPEND | O_CREAT | O_CLOEXEC, 0644);
    });
    if (fd_ < 0) {
        failWrite(path_, errno, 0);
    }
}

AppendFile::~AppendFile() {
    if (fd_ >= 0) {
        ::close(fd_);
    }
}

void AppendFile::append(std::span<const std::byte> bytes) {
    const off_t before = ::lseek(fd_, 0, SEEK_END);
    try {
        writeAllTo(fd_, path_, {bytes});
        // Delayed allocation can report a full disk only here.
        if (unlessInjected(IoCall::Sync, [&] { return ::fsync(fd_); }) != 0) {
            failWrite(path_, errno, bytes.size());
        }
    } catch (...) {
        // A record cut short by a full disk would glue the next one onto it.
        if (before >= 0 && ::ftruncate(fd_, before) != 0) {
            // Nothing more to do: the reader skips a torn line, and the error is reported.
        }
        throw;
    }
}

void AppendFile::append(std::string_view text) {
    append(std::as_bytes(std::span(text.data(), text.size())));
}

} // namespace steerseg::files
