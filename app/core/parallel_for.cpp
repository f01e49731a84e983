#include "core/parallel_for.hpp"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <system_error>
#include <thread>
#include <vector>

namespace steerseg {

unsigned parallelWorkers(std::size_t count, unsigned workers) {
    if (workers == 0) {
        workers = std::max(1U, std::thread::hardware_concurrency());
    }
    return static_cast<unsigned>(std::min<std::size_t>(workers, std::max<std::size_t>(count, 1)));
}

void parallelFor(std::size_t count, const std::function<void(std::size_t)>& body,
                 unsigned workers) {
    std::atomic<std::size_t> next{0};
    std::atomic<bool> failed{false};
    std::exception_ptr first;
    std::mutex firstMutex;
    const auto work = [&] {
        for (std::size_t i = next++; i < count && !failed.load(); i = next++) {
            try {
                body(i);
            } catch (...) {
                const std::lock_guard<std::mutex> lock(firstMutex);
                if (!first) {
                    first = std::current_exception();
                }
                failed = true;
            }
        }
    };
    std::vector<std::thread> threads;
    const unsigned n = parallelWorkers(count, workers);
    threads.reserve(n - 1);
    try {
        for (unsigned t = 1; t < n; ++t) {
            threads.emplace_back(work);
        }
    } catch (const std::system_error&) {
        // No thread to be had (a process at its limit): the ones started and this one do it.
    }
    work();
    for (std::thread& t : threads) {
        t.join();
    }
    if (first) {
        std::rethrow_exception(first);
    }
}

} // namespace steerseg
