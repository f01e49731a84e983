// Work split over the cores (core/parallel_for).
#include "core/parallel_for.hpp"

#include <atomic>
#include <gtest/gtest.h>
#include <stdexcept>
#include <vector>

namespace steerseg {
namespace {

TEST(ParallelFor, EveryIndexOnceWhateverTheWorkers) {
    for (const unsigned workers : {1U, 2U, 7U, 0U}) {
        std::vector<std::atomic<int>> calls(1000);
        parallelFor(
            calls.size(), [&](std::size_t i) { ++calls[i]; }, workers);
        for (std::size_t i = 0; i < calls.size(); ++i) {
            ASSERT_EQ(calls[i].load(), 1) << "index " << i << ", " << workers << " workers";
        }
    }
    int none = 0;
    parallelFor(0, [&](std::size_t) { ++none; });
    EXPECT_EQ(none, 0);
}

TEST(ParallelFor, WorkersAreTheCoresAtMostThePieces) {
    EXPECT_EQ(parallelWorkers(3, 8), 3U);
    EXPECT_EQ(parallelWorkers(100, 4), 4U);
    EXPECT_EQ(parallelWorkers(0, 4), 1U);
    EXPECT_GE(parallelWorkers(100), 1U);
}

TEST(ParallelFor, AThrownErrorReachesTheCallerAfterEveryWorkerEnded) {
    for (const unsigned workers : {1U, 4U}) {
        std::atomic<int> running{0};
        std::atomic<int> done{0};
        try {
            parallelFor(
                64,
                [&](std::size_t i) {
                    ++running;
                    if (i == 5) {
                        --running;
                        throw std::runtime_error("piece 5 failed");
                    }
                    ++done;
                    --running;
                },
                workers);
            FAIL() << "the error was swallowed";
        } catch (const std::runtime_error& e) {
            EXPECT_STREQ(e.what(), "piece 5 failed");
        }
        EXPECT_EQ(running.load(), 0); // no worker still at work when the error arrives
        if (workers == 1) {
            EXPECT_EQ(done.load(), 5); // the pieces after the failed one are skipped
        }
    }
}

} // namespace
} // namespace steerseg
