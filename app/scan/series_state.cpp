#include "scan/series_state.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <system_error>
#include <unistd.h>

namespace steerseg::scan {
namespace {

namespace fs = std::filesystem;

bool isMark(const fs::path& file) {
    return file.filename().string().rfind(kReceivingMarkPrefix, 0) == 0;
}

// Whether the mark's writer is gone: its lock can be taken (and is let go at once).
bool dead(const fs::path& file) {
    const int fd = ::open(file.c_str(), O_RDONLY | O_CLOEXEC | O_NOFOLLOW);
    if (fd < 0) {
        return false; // removed meanwhile: its series was finished
    }
    const bool free = ::flock(fd, LOCK_SH | LOCK_NB) == 0;
    ::close(fd); // lets go of the lock
    return free;
}

std::vector<fs::path> marksIn(const fs::path& folder) {
    std::vector<fs::path> marks;
    std::error_code ec;
    for (const auto& item : fs::directory_iterator(folder, ec)) {
        if (isMark(item.path())) {
            marks.push_back(item.path());
        }
    }
    return marks;
}

} // namespace

SeriesState seriesState(const fs::path& folder) {
    SeriesState state;
    for (const fs::path& mark : marksIn(folder)) {
        (dead(mark) ? state.incomplete : state.receiving) = true;
    }
    return state;
}

std::vector<fs::path> deadSeriesMarks(const fs::path& folder) {
    std::vector<fs::path> marks = marksIn(folder);
    std::erase_if(marks, [](const fs::path& mark) { return !dead(mark); });
    return marks;
}

} // namespace steerseg::scan
