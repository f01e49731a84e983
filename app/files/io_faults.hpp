#pragma once

// The seam where the fault-injection suite (tests/files/faults_every_writer_test.cpp) makes a
// system call of the write path fail with the errno a failing disk would give, at the n-th call
// of its kind, the way SQLite tests every I/O error. Every file the product writes goes through
// file_write.cpp or file_append.cpp, which ask here before each call; unarmed it costs one
// relaxed atomic load.
#include <cerrno>
#include <cstddef>

namespace steerseg::files {

enum class IoCall {
    Open,       // creating the temporary file, or opening a file to append to
    Write,      // each write() of the bytes
    Sync,       // fsync of the file
    Rename,     // the temporary file over the target
    SyncFolder, // fsync of the folder after the rename: the new file is already in place
};
inline constexpr std::size_t kIoCallCount = 5;

// While alive: counts the calls of each kind from zero, and makes call `nth` (0-based) of kind
// `call` fail with `error` without reaching the system. A negative `nth` fails nothing and only
// counts. One at a time per process.
class IoFault {
  public:
    IoFault(IoCall call, int nth, int error);
    ~IoFault();
    IoFault(const IoFault&) = delete;
    IoFault& operator=(const IoFault&) = delete;
    // Calls of `kind` seen so far, the failed one included.
    [[nodiscard]] std::size_t calls(IoCall kind) const;
    [[nodiscard]] bool fired() const;
};

// The errno call `call` must fail with now, or 0 to make it for real.
int injectedError(IoCall call);

// Makes the system call `call` stands for, unless a fault fails it first: -1 and errno as the
// system would give them.
template <class Call> auto unlessInjected(IoCall kind, Call&& call) -> decltype(call()) {
    if (const int error = injectedError(kind); error != 0) {
        errno = error;
        return -1;
    }
    return call();
}

} // namespace steerseg::files
