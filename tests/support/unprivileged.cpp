#include "support/unprivileged.hpp"

#include <cerrno>
#include <cstring>
#include <grp.h>
#include <stdexcept>
#include <sys/wait.h>
#include <unistd.h>

namespace steerseg::test {

namespace {

void writeAll(int fd, const std::string& text) {
    std::size_t done = 0;
    while (done < text.size()) {
        const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
        if (n <= 0) {
            return;
        }
        done += static_cast<std::size_t>(n);
    }
}

} // namespace

std::string runUnprivileged(const std::function<std::string()>& fn) {
    if (::geteuid() != 0) {
        return fn();
    }
    int fds[2];
    if (::pipe(fds) != 0) {
        throw std::runtime_error(std::string("pipe: ") + std::strerror(errno));
    }
    const pid_t child = ::fork();
    if (child < 0) {
        throw std::runtime_error(std::string("fork: ") + std::strerror(errno));
    }
    if (child == 0) {
        ::close(fds[0]);
        // Groups first: once the uid is dropped, setgroups is refused.
        if (::setgroups(0, nullptr) != 0 || ::setgid(kUnprivilegedGid) != 0 ||
            ::setuid(kUnprivilegedUid) != 0) {
            writeAll(fds[1], std::string("cannot drop privileges: ") + std::strerror(errno));
            ::_exit(2);
        }
        int status = 0;
        std::string result;
        try {
            result = fn();
        } catch (const std::exception& e) {
            result = std::string("exception: ") + e.what();
            status = 3;
        }
        writeAll(fds[1], result);
        ::_exit(status);
    }
    ::close(fds[1]);
    std::string out;
    char buffer[4096];
    ssize_t n = 0;
    while ((n = ::read(fds[0], buffer, sizeof buffer)) > 0 || (n < 0 && errno == EINTR)) {
        if (n > 0) {
            out.append(buffer, static_cast<std::size_t>(n));
        }
    }
    ::close(fds[0]);
    int status = 0;
    while (::waitpid(child, &status, 0) < 0 && errno == EINTR) {
    }
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
        throw std::runtime_error("the unprivileged child failed: " + out);
    }
    return out;
}

} // namespace steerseg::test
