#include "net/store_retention.hpp"

namespace steerseg::net {
namespace {

namespace fs = std::filesystem;

// The newest modification time of the files in `series` (the folder's own when it is empty).
fs::file_time_type newest(const fs::path& series) {
    std::error_code ec;
    fs::file_time_type latest = fs::last_write_time(series, ec);
    for (const auto& f : fs::directory_iterator(series, ec)) {
        const auto t = fs::last_write_time(f.path(), ec);
        if (!ec && t > latest) {
            latest = t;
        }
    }
    return latest;
}

} // namespace

int pruneStore(const fs::path& store, std::chrono::hours keep, fs::file_time_type now) {
    int removed = 0;
    std::error_code ec;
    for (const auto& study : fs::directory_iterator(store, ec)) {
        if (!study.is_directory()) {
            continue;
        }
        std::error_code inner;
        for (const auto& series : fs::directory_iterator(study.path(), inner)) {
            if (series.is_directory() && newest(series.path()) < now - keep) {
                std::error_code gone;
                fs::remove_all(series.path(), gone);
                removed += gone ? 0 : 1;
            }
        }
        if (fs::is_empty(study.path(), inner)) {
            fs::remove(study.path(), inner);
        }
    }
    return removed;
}

} // namespace steerseg::net
