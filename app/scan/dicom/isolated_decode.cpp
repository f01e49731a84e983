#include "scan/dicom/isolated_decode.hpp"

#include "scan/scan_reader.hpp"

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstring>
#include <string>
#include <sys/mman.h>
#include <sys/wait.h>
#include <system_error>
#include <thread>
#include <unistd.h>

namespace steerseg::scan {

namespace {

constexpr int kDecodeFailed = 3; // decode returned false
constexpr int kDecodeThrew = 4;  // decode threw

// Owns the shared mapping the child decodes into.
class SharedBuffer {
  public:
    explicit SharedBuffer(std::size_t bytes) : bytes_(bytes == 0 ? 1 : bytes) {
        data_ = mmap(nullptr, bytes_, PROT_READ | PROT_WRITE, MAP_SHARED | MAP_ANONYMOUS, -1, 0);
    }
    ~SharedBuffer() {
        if (data_ != MAP_FAILED) {
            munmap(data_, bytes_);
        }
    }
    SharedBuffer(const SharedBuffer&) = delete;
    SharedBuffer& operator=(const SharedBuffer&) = delete;
    [[nodiscard]] bool ok() const { return data_ != MAP_FAILED; }
    [[nodiscard]] char* data() const { return static_cast<char*>(data_); }

  private:
    std::size_t bytes_;
    void* data_ = MAP_FAILED;
};

[[noreturn]] void runChild(const std::function<bool(char*)>& decode, char* buffer) {
    // The child must die of its own faults, not hand them to a fuzzer's or sanitizer's handler
    // inherited from the parent.
    for (const int sig : {SIGABRT, SIGSEGV, SIGBUS, SIGFPE, SIGILL}) {
        std::signal(sig, SIG_DFL);
    }
    int code = 0;
    try {
        code = decode(buffer) ? 0 : kDecodeFailed;
    } catch (...) {
        code = kDecodeThrew;
    }
    _exit(code); // no atexit handlers, no flushing of the parent's buffers
}

// ASan's allocator (GCC 12's libsanitizer) takes none of its locks around fork(): a child
// forked while another thread holds one waits for it forever at its first allocation (a kiosk
// under ASan hung so at the first JPEG 2000 frame of a series, its GL driver's and DICOM node's
// threads allocating beside the load; glibc's malloc, which the product uses, is fork-safe).
// So a sanitizer build with other threads running decodes in-process (the readers' tests too:
// log4cplus, which DCMTK's logging loads, has started its pool's threads by then); one thread
// alone (the fuzzers) forks as the product does.
bool forkIsSafe() {
#if defined(__SANITIZE_ADDRESS__)
    std::error_code ec;
    std::size_t threads = 0;
    for (auto it = std::filesystem::directory_iterator("/proc/self/task", ec);
         !ec && it != std::filesystem::directory_iterator(); it.increment(ec)) {
        ++threads;
    }
    return !ec && threads == 1;
#else
    return true;
#endif
}

} // namespace

bool decodeIsolated(const std::filesystem::path& file, std::span<char> out,
                    const std::function<bool(char*)>& decode, int timeoutSeconds) {
    if (!forkIsSafe()) {
        return decode(out.data());
    }
    SharedBuffer shared(out.size());
    if (!shared.ok()) {
        throw ScanError(file, "cannot map " + std::to_string(out.size()) +
                                  " bytes for decoding the pixel data (" + std::strerror(errno) +
                                  ")");
    }
    const pid_t child = fork();
    if (child < 0) {
        throw ScanError(file, std::string("cannot start the pixel decoder (fork: ") +
                                  std::strerror(errno) + ")");
    }
    if (child == 0) {
        runChild(decode, shared.data());
    }
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(timeoutSeconds);
    int status = 0;
    for (;;) {
        const pid_t done = waitpid(child, &status, WNOHANG);
        if (done == child) {
            break;
        }
        if (done < 0 && errno != EINTR) {
            throw ScanError(file, std::string("lost the pixel decoder (waitpid: ") +
                                      std::strerror(errno) + ")");
        }
        if (std::chrono::steady_clock::now() > deadline) {
            kill(child, SIGKILL);
            waitpid(child, &status, 0);
            throw ScanError(file, "decoding the pixel data took more than " +
                                      std::to_string(timeoutSeconds) + " s; stopped");
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    if (WIFSIGNALED(status)) {
        throw ScanError(file, "the compressed pixel data is malformed: the decoder crashed on it "
                              "(signal " +
                                  std::to_string(WTERMSIG(status)) + ")");
    }
    const int code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    if (code == kDecodeFailed) {
        return false;
    }
    if (code != 0) {
        throw ScanError(file, "the compressed pixel data is malformed: the decoder failed on it "
                              "(exit status " +
                                  std::to_string(code) + ")");
    }
    std::memcpy(out.data(), shared.data(), out.size());
    return true;
}

} // namespace steerseg::scan
