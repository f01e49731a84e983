#pragma once

// A program run in the background for a test that must act on it while it runs (inject input,
// read the screen), with its output in files and a deadline for its exit.
#include <chrono>
#include <filesystem>
#include <optional>
#include <string>
#include <sys/types.h>
#include <vector>

namespace steerseg::test {

class ChildProcess {
  public:
    // Starts argv[0] (a path) with stdout and stderr written to `out` and `err`. Throws
    // std::runtime_error if it cannot be started.
    ChildProcess(const std::vector<std::string>& argv, const std::filesystem::path& out,
                 const std::filesystem::path& err);
    // A child still running is stopped (SIGTERM, then SIGKILL) and reaped.
    ~ChildProcess();
    ChildProcess(const ChildProcess&) = delete;
    ChildProcess& operator=(const ChildProcess&) = delete;

    // Whether it is still running (reaps it once it has exited).
    [[nodiscard]] bool running();
    // Its exit status once it has exited: the exit code, or 128 + the signal that ended it;
    // nullopt if it was still running at the deadline.
    std::optional<int> wait(std::chrono::milliseconds timeout);
    [[nodiscard]] std::optional<int> exitStatus() const { return status_; }

  private:
    void reap(int waitStatus);

    pid_t pid_ = -1;
    std::optional<int> status_;
};

} // namespace steerseg::test
