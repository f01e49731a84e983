// How deep a voxel lies in a mask (core/mask_depth): the exact distance against brute force, and
// the part of a mask deeper than a depth, which an erase's run may not take back
// (docs/steering.md).
#include "core/mask_depth.hpp"
#include "core/volume.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <random>
#include <stdexcept>

namespace steerseg {
namespace {

std::size_t countOf(const glm::ivec3& d) {
    return static_cast<std::size_t>(d.x) * static_cast<std::size_t>(d.y) *
           static_cast<std::size_t>(d.z);
}

TEST(MaskDepth, DistancesAreExactOnAnAnisotropicGrid) {
    // Against brute force: every voxel's nearest site, in mm, on random sites.
    const glm::ivec3 dims{9, 7, 5};
    const glm::dvec3 spacing{0.8, 1.3, 2.5};
    std::mt19937 rng(7);
    std::vector<std::uint8_t> sites(countOf(dims), 0);
    for (auto& s : sites) {
        s = rng() % 17 == 0 ? 1 : 0;
    }
    const std::vector<float> d = distanceToSitesMm(dims, spacing, sites, false);
    for (int k = 0; k < dims.z; ++k) {
        for (int j = 0; j < dims.y; ++j) {
            for (int i = 0; i < dims.x; ++i) {
                double best = INFINITY;
                for (int c = 0; c < dims.z; ++c) {
                    for (int b = 0; b < dims.y; ++b) {
                        for (int a = 0; a < dims.x; ++a) {
                            if (sites[linearIndex(dims, a, b, c)] != 0) {
                                best = std::min(
                                    best, glm::length(glm::dvec3(i - a, j - b, k - c) * spacing));
                            }
                        }
                    }
                }
                EXPECT_NEAR(d[linearIndex(dims, i, j, k)], best, 1e-4) << i << "," << j << "," << k;
            }
        }
    }
}

// A box of 2 mm slices: deeper than 3 mm means all but its top and bottom slices
// (4 mm from the outside beyond them) and the voxels more than three in from its sides.
TEST(MaskDepth, DeeperThanADepthIsTheMaskLessItsRimInMm) {
    const glm::ivec3 dims{20, 18, 12};
    const glm::dvec3 spacing{1.0, 1.0, 2.0};
    std::vector<std::uint8_t> mask(countOf(dims), 0);
    for (int k = 2; k <= 9; ++k) {
        for (int j = 3; j <= 14; ++j) {
            for (int i = 4; i <= 15; ++i) {
                mask[linearIndex(dims, i, j, k)] = 1;
            }
        }
    }
    const std::vector<std::uint8_t> deep = deeperThan(dims, spacing, mask, 3.0);
    for (int k = 0; k < dims.z; ++k) {
        for (int j = 0; j < dims.y; ++j) {
            for (int i = 0; i < dims.x; ++i) {
                const bool expected = i >= 7 && i <= 12 && j >= 6 && j <= 11 && k >= 3 && k <= 8;
                EXPECT_EQ(deep[linearIndex(dims, i, j, k)] != 0, expected)
                    << i << "," << j << "," << k;
            }
        }
    }
    // Depth 0 keeps the whole mask; a mask without an outside voxel on the grid is all deep.
    EXPECT_EQ(deeperThan(dims, spacing, mask, 0.0), mask);
    const std::vector<std::uint8_t> full(countOf(dims), 1);
    EXPECT_EQ(deeperThan(dims, spacing, full, 50.0), full);
    const std::vector<std::uint8_t> empty(countOf(dims), 0);
    EXPECT_EQ(deeperThan(dims, spacing, empty, 1.0), empty);
}

TEST(MaskDepth, RefusesAMaskOfAnotherSizeAndABadDepth) {
    const glm::ivec3 dims{4, 4, 4};
    const std::vector<std::uint8_t> mask(countOf(dims), 1);
    EXPECT_THROW((void)deeperThan(dims, glm::dvec3(1.0), std::vector<std::uint8_t>(63, 1), 1.0),
                 std::invalid_argument);
    EXPECT_THROW((void)deeperThan(dims, glm::dvec3(1.0), mask, -1.0), std::invalid_argument);
    EXPECT_THROW((void)deeperThan(dims, glm::dvec3(1.0), mask, NAN), std::invalid_argument);
}

} // namespace
} // namespace steerseg
