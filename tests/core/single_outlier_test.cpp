// Grubbs' test for one outlier (core/single_outlier.hpp): its critical values are the published
// table's, it finds one stray value, and it leaves a tail of many alone.
#include "core/single_outlier.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <limits>
#include <random>
#include <stdexcept>
#include <vector>

namespace steerseg::test {
namespace {

// Two-sided, alpha 0.05 (NIST/SEMATECH e-Handbook, 1.3.5.17, and Grubbs' own table).
TEST(SingleOutlier, CriticalValuesAreTheTables) {
    EXPECT_NEAR(grubbsCritical(3, 0.05), 1.155, 1e-3);
    EXPECT_NEAR(grubbsCritical(10, 0.05), 2.290, 1e-3);
    EXPECT_NEAR(grubbsCritical(20, 0.05), 2.709, 1e-3);
    EXPECT_NEAR(grubbsCritical(100, 0.05), 3.384, 1e-3);
    EXPECT_THROW((void)grubbsCritical(2, 0.05), std::invalid_argument);
    EXPECT_THROW((void)grubbsCritical(10, 0.0), std::invalid_argument);
}

// The kidney's probe (docs/steering.md): one voxel of contrast beside 18 of soft tissue.
TEST(SingleOutlier, FindsOneStrayValue) {
    std::vector<double> v{-49, -30, -21, -12, -8, -3, 0, 2, 5, 7, 9, 12, 14, 17, 20, 24, 28, 34};
    EXPECT_FALSE(singleOutlier(v).has_value());
    v.insert(v.begin() + 7, 600.0);
    ASSERT_TRUE(singleOutlier(v).has_value());
    EXPECT_EQ(*singleOutlier(v), 7U);
    v[7] = -700.0; // either side
    EXPECT_EQ(singleOutlier(v), std::optional<std::size_t>(7U));
}

// Partial volume: 13 % of a probe in a tail up to four spreads out. The tail widens the spread it
// is measured in, so nothing is left out.
TEST(SingleOutlier, LeavesATailOfManyAlone) {
    std::mt19937 engine(5);
    std::normal_distribution<double> tissue(30.0, 4.0);
    std::uniform_real_distribution<double> tail(34.0, 46.0);
    std::vector<double> v;
    for (int n = 0; n < 1309; ++n) {
        v.push_back(n % 8 == 0 ? tail(engine) : tissue(engine));
    }
    EXPECT_FALSE(singleOutlier(v).has_value());
}

TEST(SingleOutlier, NoneForTooFewEqualOrNonFiniteValues) {
    EXPECT_FALSE(singleOutlier(std::vector<double>{1.0, 100.0}).has_value());
    EXPECT_FALSE(singleOutlier(std::vector<double>(10, 7.0)).has_value());
    std::vector<double> v(10, 7.0);
    v[3] = std::numeric_limits<double>::quiet_NaN();
    EXPECT_FALSE(singleOutlier(v).has_value());
    v[3] = std::numeric_limits<double>::infinity();
    EXPECT_FALSE(singleOutlier(v).has_value());
}

} // namespace
} // namespace steerseg::test
