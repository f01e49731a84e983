#include "support/notify_socket.hpp"

#include <cerrno>
#include <chrono>
#include <cstring>
#include <poll.h>
#include <stdexcept>
#include <sys/socket.h>
#include <sys/un.h>
#include <unistd.h>

namespace steerseg::test {

NotifySocket::NotifySocket(const std::filesystem::path& dir) : path_((dir / "notify").string()) {
    sockaddr_un address{};
    address.sun_family = AF_UNIX;
    if (path_.size() >= sizeof address.sun_path) {
        throw std::runtime_error("notify socket path too long: " + path_);
    }
    std::memcpy(address.sun_path, path_.c_str(), path_.size() + 1);
    fd_ = ::socket(AF_UNIX, SOCK_DGRAM | SOCK_CLOEXEC, 0);
    std::filesystem::remove(path_);
    if (fd_ < 0 || ::bind(fd_, reinterpret_cast<const sockaddr*>(&address), sizeof address) != 0) {
        throw std::runtime_error("cannot bind " + path_ + ": " + std::strerror(errno));
    }
    reader_ = std::thread([this] { read(); });
}

NotifySocket::~NotifySocket() {
    stop_ = true;
    reader_.join();
    ::close(fd_);
    std::error_code ec;
    std::filesystem::remove(path_, ec);
}

void NotifySocket::read() {
    char buffer[4096];
    while (!stop_) {
        pollfd p{fd_, POLLIN, 0};
        if (::poll(&p, 1, 20) <= 0) {
            continue;
        }
        const ssize_t n = ::recv(fd_, buffer, sizeof buffer, MSG_DONTWAIT);
        if (n >= 0) {
            const std::lock_guard lock(mutex_);
            messages_.emplace_back(buffer, static_cast<std::size_t>(n));
        }
    }
}

std::vector<std::string> NotifySocket::receive() {
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    const std::lock_guard lock(mutex_);
    return messages_;
}

} // namespace steerseg::test
