#include "workflow/utc_time.hpp"

#include <algorithm>
#include <array>
#include <cstdio>
#include <ctime>

namespace steerseg::workflow {

namespace {

struct Utc {
    std::tm tm{};
    int millis = 0;
};

Utc utc(std::chrono::system_clock::time_point t) {
    using namespace std::chrono;
    // Whole seconds rounded down, so times before 1970 keep a positive millisecond part.
    const auto secs = floor<seconds>(t);
    Utc u;
    u.millis = static_cast<int>(duration_cast<milliseconds>(t - secs).count());
    const std::time_t tt = system_clock::to_time_t(secs);
    gmtime_r(&tt, &u.tm);
    return u;
}

} // namespace

std::string isoUtc(std::chrono::system_clock::time_point t) {
    const Utc u = utc(t);
    std::array<char, 64> buf{};
    const int n = std::snprintf(buf.data(), buf.size(), "%04d-%02d-%02dT%02d:%02d:%02d.%03dZ",
                                u.tm.tm_year + 1900, u.tm.tm_mon + 1, u.tm.tm_mday, u.tm.tm_hour,
                                u.tm.tm_min, u.tm.tm_sec, u.millis);
    return {buf.data(), std::min(static_cast<std::size_t>(std::max(n, 0)), buf.size() - 1)};
}

std::string compactUtc(std::chrono::system_clock::time_point t) {
    const Utc u = utc(t);
    std::array<char, 64> buf{};
    const int n =
        std::snprintf(buf.data(), buf.size(), "%04d%02d%02d-%02d%02d%02d", u.tm.tm_year + 1900,
                      u.tm.tm_mon + 1, u.tm.tm_mday, u.tm.tm_hour, u.tm.tm_min, u.tm.tm_sec);
    return {buf.data(), std::min(static_cast<std::size_t>(std::max(n, 0)), buf.size() - 1)};
}

} // namespace steerseg::workflow
