#include "scan/read_progress.hpp"

namespace steerseg::scan {

namespace {
thread_local std::atomic<std::uint64_t>* t_counter = nullptr;
} // namespace

void countReadsInto(std::atomic<std::uint64_t>* counter) {
    t_counter = counter;
}

void noteBytesRead(std::uint64_t bytes) {
    if (t_counter != nullptr) {
        t_counter->fetch_add(bytes, std::memory_order_relaxed);
    }
}

} // namespace steerseg::scan
