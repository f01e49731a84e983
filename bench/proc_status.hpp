#pragma once

// A field of /proc/self/status in bytes (VmRSS, VmHWM), 0 when absent: the benchmarks' peak
// host memory, steerseg's and ITK's readers measured the same way.
#include <cstdlib>
#include <fstream>
#include <string>

namespace steerseg::bench {

inline double statusBytes(const char* field) {
    std::ifstream in("/proc/self/status");
    std::string line;
    const std::string key = std::string(field) + ":";
    while (std::getline(in, line)) {
        if (line.rfind(key, 0) == 0) {
            return std::atof(line.c_str() + key.size()) * 1024.0;
        }
    }
    return 0.0;
}

} // namespace steerseg::bench
