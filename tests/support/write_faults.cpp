#include "support/write_faults.hpp"

#include "files/file_error.hpp"

#include <fstream>
#include <iterator>
#include <signal.h>
#include <sstream>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

namespace steerseg::test {

std::string readText(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

std::size_t entryCount(const std::filesystem::path& dir) {
    return static_cast<std::size_t>(std::distance(std::filesystem::directory_iterator(dir), {}));
}

std::string writeErrorOf(const std::function<void()>& write) {
    try {
        write();
    } catch (const files::WriteError& e) {
        return e.what();
    }
    return "";
}

std::string writeErrorUnderSizeLimit(const std::function<void()>& write, std::size_t limitBytes) {
    int pipeFds[2];
    if (::pipe(pipeFds) != 0) {
        return "no pipe";
    }
    const pid_t child = ::fork();
    if (child < 0) {
        return "no fork";
    }
    if (child == 0) {
        ::close(pipeFds[0]);
        // Past the limit write() fails with EFBIG instead of the process dying of SIGXFSZ.
        ::signal(SIGXFSZ, SIG_IGN);
        const rlimit limit{limitBytes, limitBytes};
        ::setrlimit(RLIMIT_FSIZE, &limit);
        const std::string m = writeErrorOf(write);
        const ssize_t written = ::write(pipeFds[1], m.data(), m.size());
        ::_exit(written == static_cast<ssize_t>(m.size()) ? 0 : 1);
    }
    ::close(pipeFds[1]);
    std::string m;
    char buffer[512];
    for (ssize_t n = 0; (n = ::read(pipeFds[0], buffer, sizeof buffer)) > 0;) {
        m.append(buffer, static_cast<std::size_t>(n));
    }
    ::close(pipeFds[0]);
    int status = 0;
    ::waitpid(child, &status, 0);
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
        return "the writing child failed: " + m;
    }
    return m;
}

} // namespace steerseg::test
