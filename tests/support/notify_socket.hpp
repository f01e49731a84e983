#pragma once

// A service manager's end of sd_notify(3) for tests: a Unix datagram socket bound in a
// temporary folder, whose path goes into NOTIFY_SOCKET. A thread reads it as systemd does,
// at once: a datagram socket holds only net.unix.max_dgram_qlen messages (10 by default), and
// a sender blocks on a full one.
#include <atomic>
#include <filesystem>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace steerseg::test {

class NotifySocket {
  public:
    explicit NotifySocket(const std::filesystem::path& dir);
    ~NotifySocket();
    NotifySocket(const NotifySocket&) = delete;
    NotifySocket& operator=(const NotifySocket&) = delete;

    [[nodiscard]] const std::string& path() const { return path_; }
    // Every datagram received so far (after a short wait for any still in the socket).
    std::vector<std::string> receive();

  private:
    void read();

    int fd_ = -1;
    std::string path_;
    std::atomic<bool> stop_{false};
    std::mutex mutex_;
    std::vector<std::string> messages_;
    std::thread reader_;
};

} // namespace steerseg::test
