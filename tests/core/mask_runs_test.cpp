#include "core/mask_runs.hpp"

#include <gtest/gtest.h>
#include <random>
#include <stdexcept>

namespace steerseg::test {
namespace {

TEST(MaskRuns, RoundTripsAnyMask) {
    std::mt19937 rng(7);
    for (int trial = 0; trial < 50; ++trial) {
        std::vector<std::uint8_t> mask(static_cast<std::size_t>(rng() % 5000));
        const unsigned density = rng() % 10;
        for (auto& v : mask) {
            v = (rng() % 10) < density ? static_cast<std::uint8_t>(1 + rng() % 3) : 0;
        }
        const MaskRuns runs = encodeRuns(mask);
        const std::vector<std::uint8_t> back = decodeRuns(runs);
        ASSERT_EQ(back.size(), mask.size());
        for (std::size_t n = 0; n < mask.size(); ++n) {
            ASSERT_EQ(back[n] != 0, mask[n] != 0) << n;
        }
    }
    EXPECT_TRUE(encodeRuns({}).runs.empty());
}

TEST(MaskRuns, ABlobIsAFewRunsAndBadRunsAreRefused) {
    std::vector<std::uint8_t> mask(1000, 0);
    std::fill(mask.begin() + 100, mask.begin() + 300, 1);
    EXPECT_EQ(encodeRuns(mask).runs, (std::vector<std::uint32_t>{100, 200, 700}));
    EXPECT_THROW(decodeRuns({10, {5, 6}}), std::invalid_argument);
    EXPECT_THROW(decodeRuns({10, {5, 4}}), std::invalid_argument);
}

} // namespace
} // namespace steerseg::test
