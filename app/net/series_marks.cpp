#include "net/series_marks.hpp"

#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <ctime>
#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

namespace steerseg::net {
namespace {

namespace fs = std::filesystem;

std::atomic<unsigned> nextMark{0};

bool syncFolder(const fs::path& folder) {
    const int fd = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd < 0) {
        return false;
    }
    const bool ok = ::fsync(fd) == 0;
    ::close(fd);
    return ok;
}

std::string now() {
    const std::time_t t = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
    std::tm utc{};
    ::gmtime_r(&t, &utc);
    char text[32];
    std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &utc);
    return text;
}

} // namespace

SeriesMarks::SeriesMarks(std::string who) : who_(std::move(who)) {}

SeriesMarks::~SeriesMarks() {
    finish(false);
}

std::string SeriesMarks::mark(const fs::path& folder) {
    for (const Mark& m : marks_) {
        if (m.folder == folder) {
            return {};
        }
    }
    Mark m;
    m.folder = folder;
    m.stale = scan::deadSeriesMarks(folder);
    // Unique within the process and across its restarts (the pid and the time).
    const std::string name = std::to_string(::getpid()) + "-" + std::to_string(std::time(nullptr)) +
                             "-" + std::to_string(nextMark++);
    m.file = folder / (scan::kReceivingMarkPrefix + name);
    // Made and locked under another name, then renamed (the lock goes with the file): nobody
    // looking for marks ever sees this one unlocked while its association is open.
    const fs::path making = folder / (".marking-" + name);
    m.fd = ::open(making.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC | O_NOFOLLOW, 0644);
    if (m.fd < 0) {
        return "cannot mark the series as being received: " + making.string() + ": " +
               std::strerror(errno);
    }
    const std::string text = "receiving from " + who_ + " since " + now() + "\n";
    if (::flock(m.fd, LOCK_EX) != 0 ||
        ::write(m.fd, text.data(), text.size()) != static_cast<ssize_t>(text.size()) ||
        ::fsync(m.fd) != 0 || ::rename(making.c_str(), m.file.c_str()) != 0 ||
        !syncFolder(folder)) {
        const std::string why = std::strerror(errno);
        ::close(m.fd);
        std::error_code ec;
        fs::remove(making, ec);
        fs::remove(m.file, ec);
        return "cannot mark the series as being received: " + m.file.string() + ": " + why;
    }
    marks_.push_back(std::move(m));
    return {};
}

std::vector<fs::path> SeriesMarks::finish(bool whole) {
    std::vector<fs::path> folders;
    if (finished_) {
        return folders;
    }
    finished_ = true;
    for (const Mark& m : marks_) {
        folders.push_back(m.folder);
        if (whole) {
            std::error_code ec;
            fs::remove(m.file, ec);
            for (const fs::path& stale : m.stale) {
                fs::remove(stale, ec);
            }
            // A power cut after this must not bring a mark back over a whole series.
            syncFolder(m.folder);
        }
        ::close(m.fd); // a mark left is dead from here on
    }
    marks_.clear();
    return folders;
}

} // namespace steerseg::net
